#include "motion/positioning_axes.hpp"

#include <algorithm>

#include "motion/velocity_ramp.hpp"

namespace drycut::motion {

double PositioningAxes::move_time(const interp::PositioningMove& m) {
  if (!(m.travel > 1e-12) || !(m.velocity > 0) || !(m.accel > 0)) return std::max(0.0, m.lead_time_s);
  const RampLimits limits{m.accel, m.jerk > 0 ? m.jerk : kNoJerkLimit};
  // SPOS from rotation enters position control turning (entry_velocity) and brakes to rest.
  const double top = std::max(m.velocity, m.entry_velocity);
  return m.lead_time_s + plan_segment(m.entry_velocity, 0.0, top, m.travel, limits).duration;
}

void PositioningAxes::start(const interp::PositioningMove& m, double start_s) {
  double& ready = ready_at_[m.axis];
  ready = std::max(ready, start_s + move_time(m));
}

double PositioningAxes::wait(const std::vector<std::string>& axes) {
  double ready = 0;
  if (axes.empty()) {
    for (const auto& [axis, t] : ready_at_) ready = std::max(ready, t);
    ready_at_.clear();
    return ready;
  }
  for (const auto& axis : axes) {
    const auto it = ready_at_.find(axis);
    if (it == ready_at_.end()) continue;
    ready = std::max(ready, it->second);
    ready_at_.erase(it);
  }
  return ready;
}

}  // namespace drycut::motion
