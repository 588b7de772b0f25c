#include "motion/path_constraints.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "motion/cube_root.hpp"

namespace drycut::motion {
namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();

// Calls f(|Δt|, limits before, limits after) for every extra axis whose velocity share jumps at
// the junction (an axis that moves on one side only jumps from or to zero; the side without it
// lends the other side's limits).
template <class F>
void for_each_extra_jump(const Junction& j, F&& f) {
  const auto& before = j.before_dynamics.extra;
  const auto& after = j.after_dynamics.extra;
  if (before.empty() && after.empty()) return;
  auto find = [](const std::vector<ExtraAxisTerm>& terms, int axis) -> const ExtraAxisTerm* {
    for (const auto& t : terms)
      if (t.axis == axis) return &t;
    return nullptr;
  };
  for (const auto& b : before) {
    const ExtraAxisTerm* a = find(after, b.axis);
    const double dt = std::abs((a ? a->tangent : 0.0) - b.tangent);
    if (dt > 1e-12) f(dt, b, a ? *a : b);
  }
  for (const auto& a : after) {
    if (find(before, a.axis)) continue;
    if (std::abs(a.tangent) > 1e-12) f(std::abs(a.tangent), a, a);
  }
}

// Inside one run of the compressor (both sides its output, the geometry tangent-continuous) the
// control compresses the extra axes with the geometry (COMPCAD/COMPCURV polynomials; Job Planning,
// "Compression of the orientation"): their rate d(axis)/ds does not jump at the join but changes
// along the spans. drycut keeps them linear per span, so the change Δ is taken as spread over a
// length L: axis acceleration v²·Δ/L, jerk v³·Δ/L² (before 2026-11-28 the jump rules braked a
// 5-axis stream at every join). L is at most the half spans either side, (L_before + L_after)/2,
// and at most 8·tol/Δ: a change rounded over L leaves the kinked course by Δ·L/8 at the join (a
// parabola's blend), which the fit must keep within the axis's MD33100 tolerance. A smooth
// course (the swing-door cut its spans at that tolerance) gets about its span lengths; a sudden
// turn (8 deg/mm among 0.2 deg/mm blocks) a short L, so the axis is held back there. Until
// 2026-11-29 a change above half the larger rate kept the jump rules instead, which braked to a
// few mm/min where a rotary axis turns round (its rate changes sign) or starts from rest.
bool extra_axes_smoothed(const Junction& j) {
  return j.before.compressed_blocks > 0 && j.after.compressed_blocks > 0 &&
         (j.after_start.tangent - j.before_end.tangent).norm() < 1e-6;
}

double smoothing_length(const Junction& j, double dt, const ExtraAxisTerm& before, const ExtraAxisTerm& after) {
  const double tolerance = std::min(before.compress_tol, after.compress_tol);
  return std::min(0.5 * (j.before_dynamics.length + j.after_dynamics.length), 8.0 * tolerance / dt);
}

}  // namespace

double FeedConstraint::max_velocity(const ElementDynamics& d, const CurvePoint&) const {
  return d.rapid ? kInf : d.feed;
}

double AxisVelocityConstraint::max_velocity(const ElementDynamics& d, const CurvePoint& p) const {
  double v = kInf;
  for (int i = 0; i < 3; ++i) {
    const double t = std::abs(p.tangent[i]);
    if (t > 1e-12) v = std::min(v, d.axis_velocity[i] / t);
  }
  for (const ExtraAxisTerm& e : d.extra) {
    const double t = std::abs(e.tangent);
    if (t > 1e-12) v = std::min(v, e.velocity / t);
  }
  return v;
}

double CurvatureConstraint::max_velocity(const ElementDynamics& d, const CurvePoint& p) const {
  if (p.curvature <= 1e-12) return kInf;
  const double share = d.centripetal_share > 0 ? d.centripetal_share : 1.0;
  // sqrt is monotone and correctly rounded: the root of the smallest ratio is the smallest root.
  double v2 = kInf;
  for (int i = 0; i < 3; ++i) {
    const double k = std::abs(p.curvature_vector[i]);
    if (k > 1e-15) v2 = std::min(v2, share * d.axis_accel[i] / k);
  }
  return v2 < kInf ? std::sqrt(v2) : kInf;
}

double CurvatureJerkConstraint::max_velocity(const ElementDynamics& d, const CurvePoint& p) const {
  if (!d.soft || p.curvature <= 1e-12) return kInf;
  // One cube root, of the smallest ratio (the cube root is monotone; this one to a few ulps).
  double v3 = kInf;
  for (int i = 0; i < 3; ++i) {
    const double r = std::abs(p.curvature_rate[i]);
    if (r > 1e-15) v3 = std::min(v3, d.axis_jerk[i] / r);
  }
  return v3 < kInf ? cube_root(v3) : kInf;
}

double ShortBlockConstraint::max_velocity(const ElementDynamics& d, const CurvePoint&) const {
  if (d.inserted) return std::numeric_limits<double>::infinity();
  return d.short_block_factor * d.block_length / d.ipo_cycle;
}

bool ends_in_exact_stop(const interp::PathElement& e) {
  return e.dynamics.transition == interp::TransitionMode::ExactStop || e.dynamics.exact_stop_this_block;
}

double ExactStopConstraint::max_velocity(const Junction& j) const {
  return ends_in_exact_stop(j.before) ? 0.0 : kInf;
}

double CornerConstraint::max_velocity(const Junction& j) const {
  const Vec3 jump = j.after_start.tangent - j.before_end.tangent;
  double v = kInf;
  const double ovl = std::min(j.before_dynamics.ovl_factor, j.after_dynamics.ovl_factor) - 1.0;
  const bool smoothed = extra_axes_smoothed(j);
  for_each_extra_jump(j, [&](double dt, const ExtraAxisTerm& before, const ExtraAxisTerm& after) {
    if (smoothed)
      v = std::min(v, std::sqrt(std::min(before.accel, after.accel) * smoothing_length(j, dt, before, after) / dt));
    else
      v = std::min(v, std::min(before.raw_accel, after.raw_accel) * ovl * j.after_dynamics.ipo_cycle / dt);
  });
  if (jump.norm() < 1e-9) return v;  // tangent-continuous: no velocity jump on any geometry axis
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
  const double t = j.after_dynamics.ipo_cycle;
  double v = kInf;
  const bool smoothed = extra_axes_smoothed(j);
  for_each_extra_jump(j, [&](double dt, const ExtraAxisTerm& before, const ExtraAxisTerm& after) {
    const double l = smoothed ? smoothing_length(j, dt, before, after) : 0.0;
    if (smoothed)
      v = std::min(v, cube_root(std::min(before.jerk, after.jerk) * l * l / dt));
    else
      v = std::min(v, std::min(before.transition_jerk, after.transition_jerk) * t * t / dt);
  });
  if (jump.norm() < 1e-9) return v;
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
