#include "motion/path_constraints.hpp"

#include <cmath>
#include <limits>

#include "motion/cube_root.hpp"

namespace drycut::motion {
namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
}

double FeedConstraint::max_velocity(const ElementDynamics& d, const CurvePoint&) const {
  return d.rapid ? kInf : d.feed;
}

double AxisVelocityConstraint::max_velocity(const ElementDynamics& d, const CurvePoint& p) const {
  double v = kInf;
  for (int i = 0; i < 3; ++i) {
    const double t = std::abs(p.tangent[i]);
    if (t > 1e-12) v = std::min(v, d.axis_velocity[i] / t);
  }
  return v;
}

double CurvatureConstraint::max_velocity(const ElementDynamics& d, const CurvePoint& p) const {
  if (p.curvature <= 1e-12) return kInf;
  const double share = d.centripetal_share > 0 ? d.centripetal_share : 1.0;
  double v = kInf;
  for (int i = 0; i < 3; ++i) {
    const double k = std::abs(p.curvature_vector[i]);
    if (k > 1e-15) v = std::min(v, std::sqrt(share * d.axis_accel[i] / k));
  }
  return v;
}

double CurvatureJerkConstraint::max_velocity(const ElementDynamics& d, const CurvePoint& p) const {
  if (!d.soft || p.curvature <= 1e-12) return kInf;
  double v = kInf;
  for (int i = 0; i < 3; ++i) {
    const double r = std::abs(p.curvature_rate[i]);
    if (r > 1e-15) v = std::min(v, cube_root(d.axis_jerk[i] / r));
  }
  return v;
}

double ShortBlockConstraint::max_velocity(const ElementDynamics& d, const CurvePoint&) const {
  if (d.inserted) return std::numeric_limits<double>::infinity();
  return d.short_block_factor * d.length / d.ipo_cycle;
}

bool ends_in_exact_stop(const interp::PathElement& e) {
  return e.dynamics.transition == interp::TransitionMode::ExactStop || e.dynamics.exact_stop_this_block;
}

double ExactStopConstraint::max_velocity(const Junction& j) const {
  return ends_in_exact_stop(j.before) ? 0.0 : kInf;
}

double CornerConstraint::max_velocity(const Junction& j) const {
  const Vec3 jump = j.after_start.tangent - j.before_end.tangent;
  if (jump.norm() < 1e-9) return kInf;  // tangent-continuous: no velocity jump on any axis
  double v = kInf;
  for (int i = 0; i < 3; ++i) {
    const double dt = std::abs(jump[i]);
    if (dt < 1e-12) continue;
    const double allowed = std::min(j.before_dynamics.raw_axis_accel[i], j.after_dynamics.raw_axis_accel[i]) *
                           (std::min(j.before_dynamics.ovl_factor, j.after_dynamics.ovl_factor) - 1.0) *
                           j.after_dynamics.ipo_cycle;
    v = std::min(v, allowed / dt);
  }
  return v;
}

double TransitionJerkConstraint::max_velocity(const Junction& j) const {
  if (!j.before_dynamics.soft || !j.after_dynamics.soft) return kInf;
  const Vec3 jump = j.after_start.tangent - j.before_end.tangent;
  if (jump.norm() < 1e-9) return kInf;
  const double t = j.after_dynamics.ipo_cycle;
  double v = kInf;
  for (int i = 0; i < 3; ++i) {
    const double dt = std::abs(jump[i]);
    if (dt < 1e-12) continue;
    const double jerk = std::min(j.before_dynamics.transition_jerk[i], j.after_dynamics.transition_jerk[i]);
    v = std::min(v, jerk * t * t / dt);
  }
  return v;
}

double CurvatureStepConstraint::max_velocity(const Junction& j) const {
  if (!j.before_dynamics.soft || !j.after_dynamics.soft) return kInf;
  const Vec3 step = j.after_start.curvature_vector - j.before_end.curvature_vector;
  const double t = j.after_dynamics.ipo_cycle;
  double v = kInf;
  for (int i = 0; i < 3; ++i) {
    const double dk = std::abs(step[i]);
    if (dk < 1e-9) continue;
    const double jerk = std::min(j.before_dynamics.transition_jerk[i], j.after_dynamics.transition_jerk[i]);
    v = std::min(v, std::sqrt(jerk * t / dk));
  }
  return v;
}

std::vector<std::unique_ptr<PointConstraint>> default_point_constraints() {
  std::vector<std::unique_ptr<PointConstraint>> c;
  c.push_back(std::make_unique<FeedConstraint>());
  c.push_back(std::make_unique<AxisVelocityConstraint>());
  c.push_back(std::make_unique<CurvatureConstraint>());
  c.push_back(std::make_unique<CurvatureJerkConstraint>());
  c.push_back(std::make_unique<ShortBlockConstraint>());
  return c;
}

std::vector<std::unique_ptr<JunctionConstraint>> default_junction_constraints() {
  std::vector<std::unique_ptr<JunctionConstraint>> c;
  c.push_back(std::make_unique<ExactStopConstraint>());
  c.push_back(std::make_unique<CornerConstraint>());
  c.push_back(std::make_unique<TransitionJerkConstraint>());
  c.push_back(std::make_unique<CurvatureStepConstraint>());
  return c;
}

}  // namespace drycut::motion
