#include "motion/element_dynamics.hpp"

#include <algorithm>
#include <cmath>

namespace drycut::motion {

ElementDynamics make_element_dynamics(const interp::PathElement& element, double length,
                                      const machine::MachineProfile& profile) {
  ElementDynamics d;
  d.length = length;
  d.rapid = element.rapid;
  d.feed = element.rapid ? 0.0 : element.feed_mm_s;
  d.soft = element.dynamics.profile == interp::AccelProfile::Soft;
  // The dynamic group (DYNNORM ... DYNPREC) picks the element of the dynamic machine data; the
  // mode factors (SOFT, G0) apply on top of it.
  const machine::DynamicGroupFactors& group = profile.dynamic_groups[static_cast<size_t>(element.dynamics.group)];
  const double accel_factor = element.rapid ? profile.g0_accel_factor : (d.soft ? profile.soft_accel_factor : 1.0);
  const auto group_index = static_cast<size_t>(element.dynamics.group);
  const double jerk_factor = element.rapid ? profile.g0_jerk_factor : 1.0;
  // ACC[ax]/VELOLIM[ax]/JERKLIM[ax] scale each axis's limits (the corner rules included).
  const interp::AxisLimitFactors& programmed = element.dynamics.limits;
  for (int i = 0; i < 3; ++i) {
    const size_t k = static_cast<size_t>(i);
    const auto& axis = profile.axes[k];
    const double accel = axis.max_accel_mm_s2 * group.max_ax_accel * programmed.accel[k];
    const double jerk = axis.max_jerk_mm_s3 * group.max_ax_jerk * programmed.jerk[k];
    d.axis_velocity[i] = axis.max_velocity_mm_s * programmed.velocity[k];
    d.raw_axis_accel[i] = accel;
    d.axis_accel[i] = machine::axis_mode_accel_mm_s2(profile, k, group_index, element.rapid, d.soft) * programmed.accel[k];
    d.axis_jerk[i] = jerk * jerk_factor;
    d.transition_jerk[i] =
        (axis.transition_jerk_mm_s3 > 0 ? axis.transition_jerk_mm_s3 * group.path_trans_jerk_lim * programmed.jerk[k] : jerk) *
        jerk_factor;
  }
  d.path_jerk = profile.path_jerk_mm_s3 * group.max_path_jerk * jerk_factor;
  d.centripetal_share = profile.curv_effect_on_path_accel;
  d.ipo_cycle = profile.ipo_cycle_s;
  d.short_block_factor = profile.short_block_factor;
  // A corner-smoothing rounding is an inserted block the interpolator runs as a block of its
  // own: the short-block rule applies to it (FB1: "each block requires at least one IPO cycle").
  d.inserted = element.inserted && element.smoothing_deviation_mm < 0;
  d.block_length = element.block_length_mm > 0 ? element.block_length_mm : length;
  d.ovl_factor = profile.max_accel_ovl_factor;
  // FGROUP without some geometry axis, or extra axes in the path length: the path parameter is
  // not the curve's arc length.
  if ((!element.extra_axes.empty() || element.geometry_feed_axes != 7) && length > 0)
    d.geometry_scale = element.curve ? element.curve->length() / length : 0.0;
  if (!element.extra_axes.empty() && length > 0) {
    for (const auto& m : element.extra_axes) {
      const auto& axis = profile.extra_axes.at(static_cast<size_t>(m.axis));
      ExtraAxisTerm t;
      t.axis = m.axis;
      t.tangent = m.travel / length;
      t.velocity = axis.max_velocity_mm_s;
      t.raw_accel = axis.max_accel_mm_s2 * group.max_ax_accel;
      t.accel = t.raw_accel * accel_factor;
      t.jerk = axis.max_jerk_mm_s3 * group.max_ax_jerk * jerk_factor;
      t.transition_jerk = axis.transition_jerk_mm_s3 * group.path_trans_jerk_lim * jerk_factor;
      t.compress_tol = axis.compress_pos_tol_mm;
      d.extra.push_back(t);
    }
  }
  return d;
}

CurvePoint path_point(const ElementDynamics& d, const geometry::Curve& curve, double s) {
  if (d.geometry_scale == 1.0) return curve.at(s);
  const double k = d.geometry_scale;
  CurvePoint p = curve.at(s * k);
  if (k <= 0) {  // the geometry stands: only extra axes move
    p.tangent = Vec3::Zero();
    p.curvature_vector = Vec3::Zero();
    p.curvature_rate = Vec3::Zero();
    p.curvature = 0;
    p.curvature_derivative = 0;
    return p;
  }
  p.tangent *= k;
  p.curvature_vector *= k * k;
  p.curvature *= k * k;
  p.curvature_rate *= k * k * k;
  p.curvature_derivative *= k * k * k;
  return p;
}

RampLimits tangential_limits(const ElementDynamics& d, const CurvePoint& point) {
  // A straight point keeps the whole axis acceleration for the path; a curved one keeps the
  // centripetal share in reserve (with share 0 nothing is reserved, as on the control).
  const bool curved = point.curvature > 1e-12;
  const double keep = curved ? 1.0 - d.centripetal_share : 1.0;
  double accel = std::numeric_limits<double>::infinity();
  double jerk = d.soft ? d.path_jerk : kNoJerkLimit;
  for (int i = 0; i < 3; ++i) {
    const double t = std::abs(point.tangent[i]);
    if (t < 1e-12) continue;
    accel = std::min(accel, keep * d.axis_accel[i] / t);
    if (d.soft) jerk = std::min(jerk, d.axis_jerk[i] / t);
  }
  for (const ExtraAxisTerm& e : d.extra) {
    const double t = std::abs(e.tangent);
    if (t < 1e-12) continue;
    accel = std::min(accel, e.accel / t);  // a straight interpolation: no centripetal share
    if (d.soft) jerk = std::min(jerk, e.jerk / t);
  }
  if (!std::isfinite(accel)) accel = keep * d.axis_accel.minCoeff();
  return {accel, jerk};
}

}  // namespace drycut::motion
