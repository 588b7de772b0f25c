#include "interp/feed_rate.hpp"

#include <cmath>

namespace drycut::interp {
namespace {

constexpr double kMinSpeed = 0.001;  // S resolution: below it the spindle stands

FeedResult thread_feed(const ModalState& state, double rpm, double length, const Eigen::Vector3d& chord,
                       double change) {
  const std::string name(motion_mode_name(state.motion));
  if (state.thread_lead_mm <= 0) return {0, 14800, name + " needs a lead I, J or K"};
  if (rpm < kMinSpeed) return {0, 10860, name + " needs a turning spindle (S and M3/M4)"};
  double travel = std::abs(chord[state.thread_lead_axis]);
  if (travel < 1e-9) travel = length;
  const double lead = state.thread_lead_mm;
  double revolutions = travel / lead;
  const bool lead_changes = state.motion == MotionMode::ThreadIncreasing || state.motion == MotionMode::ThreadDecreasing;
  if (change > 0 && lead_changes) {
    revolutions = lead_change_revolutions(travel, lead, change, state.motion == MotionMode::ThreadIncreasing);
    if (revolutions < 0) return {0, 14800, "G35: the lead would reach zero inside the block"};
  }
  const double minutes = revolutions / rpm;
  if (!(minutes > 0)) return {lead * rpm / 60.0, 0, ""};
  return {length / (minutes * 60.0), 0, ""};
}

}  // namespace

double lead_change_revolutions(double travel, double lead, double change, bool increasing) {
  if (!(change > 0)) return travel / lead;
  if (increasing) return (std::sqrt(lead * lead + 2 * change * travel) - lead) / change;
  const double root = lead * lead - 2 * change * travel;
  return root < 0 ? -1.0 : (lead - std::sqrt(root)) / change;
}

FeedResult path_feed(const ModalState& state, double spindle_rpm, double length_mm, const Eigen::Vector3d& chord,
                     double lead_change_mm) {
  if (state.thread_mode()) return thread_feed(state, spindle_rpm, length_mm, chord, lead_change_mm);
  if (state.feed <= 0) return {0, 10860, "no F programmed for " + std::string(motion_mode_name(state.motion))};
  switch (state.feed_mode) {
    case FeedMode::PerMinute:
      return {state.feed * state.feed_unit_mm / 60.0, 0, ""};
    case FeedMode::PerRevolution:
      if (spindle_rpm < kMinSpeed) return {0, 10860, "feed per revolution (G95, G96, G97 or G973) needs a turning spindle (S and M3/M4)"};
      return {state.feed * state.feed_unit_mm * spindle_rpm / 60.0, 0, ""};
    case FeedMode::InverseTime:
      // A block without length has no time to fill: give it the inverse-time value itself.
      return {length_mm > 0 ? length_mm * state.feed / 60.0 : state.feed / 60.0, 0, ""};
  }
  return {0, 10860, "unknown feed mode"};
}

}  // namespace drycut::interp
