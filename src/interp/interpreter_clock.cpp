// The interpreter's clock: the nominal time of what it emitted (path length over the feed,
// rapid moves from rest to rest, dwells, tool changes), the part of it at feed with a tool active
// (tool action time), and the waits of a program that polls the clock. Timers and clock
// variables a program reads, and the spindle run-up's wait, use it while the planner is still
// behind the interpreter (docs/controller-state.md "Clock, run-time counters ...").
#include <algorithm>
#include <cmath>
#include <limits>

#include "interp/interpreter.hpp"
#include "interp/interpreter_block.hpp"
#include "interp/rest_to_rest.hpp"

namespace drycut::interp {

double Interpreter::poll_clock(uint64_t line) {
  if (line != line_at_poll_) {
    // Counted, not taken as nominal time minus the waits: that difference carries rounding
    // noise, and a pass that only waited (W1: STOPRE / IF $AC_TIMER[2]<5 GOTOB W1) then looked
    // like work, the clock stood still and the loop guard saw the same state again (990004).
    if (work_additions_ == work_at_poll_) clock_wait_s_ += profile_.ipo_cycle_s;
    work_at_poll_ = work_additions_;
    line_at_poll_ = line;
  }
  return nominal_time_s();
}

double Interpreter::extra_axis_actual_position(size_t i) const {
  const double now = nominal_time_s();
  const ExtraAxes::AsyncMove* m = extra_axes_.moving_at(extra_axes_.data(i).name, now);
  if (!m) return extra_axes_.position(i);
  const double share = positioning_share(std::abs(m->travel), m->velocity, m->accel, m->arrival_s - m->start_s, now - m->start_s);
  const double at = m->from + share * m->travel;
  return extra_axes_.data(i).modulo ? wrap_modulo(at, extra_axes_.data(i).modulo_range) : at;
}

void Interpreter::emit_clock_wait(const BlockContext& ctx) {
  // The polls since the last element: the program waited for the clock before this block.
  PathElement e = element_template(ctx, ElementKind::Dwell);
  e.dwell_s = clock_wait_s_;
  e.label = "waiting for the clock";
  clock_wait_s_ = 0.0;
  const uint64_t work = work_additions_;
  emit(std::move(e));
  work_additions_ = work;  // the wait is no work
}

void Interpreter::add_nominal_time(const PathElement& e) {
  // An estimate of the planned time (feed moves without ramps or corners, rapid moves from rest
  // to rest): enough for timers a program reads while the planner is still behind the
  // interpreter, and for the spindle run-up that G0 moves overlap.
  const double before = nominal_time_s_;
  add_element_time(e);
  if (nominal_time_s_ != before) ++work_additions_;
}

void Interpreter::add_element_time(const PathElement& e) {
  // A dwell, stop, tool change or positioning brings the path to rest; a change of modes does not.
  if (!e.is_motion() && e.kind != ElementKind::DynamicsChange) clock_at_rest_ = true;
  if (e.kind == ElementKind::Dwell) {
    nominal_time_s_ += e.dwell_s;
    if (e.run_up_wait == 0) least_time_s_ += e.dwell_s;  // (a run-up wait may come out shorter)
    return;
  }
  if (e.kind == ElementKind::ToolChange) {
    nominal_time_s_ += profile_.tool_change_time_s;
    least_time_s_ += profile_.tool_change_time_s;
    return;
  }
  if (e.kind == ElementKind::Positioning) {
    // POS/SPOS end with their block: the slowest axis from rest to rest (SPOS of a turning
    // spindle brakes first). POSA/SPOSA run beside the program and add nothing here.
    double longest = 0.0;
    for (const PositioningMove& m : e.positioning)
      if (m.block_synchronous)
        longest = std::max(longest, m.lead_time_s + move_to_rest_s(m.travel, m.entry_velocity, m.velocity, m.accel, m.jerk));
    nominal_time_s_ += longest;
    least_time_s_ += longest;
    return;
  }
  if (!e.is_motion() || !e.curve) return;
  // The length F refers to and the planner plans along: with A, C, U ... moving, their travel
  // counts (a G0 C90 or G1 A90 alone has no geometry length and took no time before 2026-11-29).
  const double length = e.path_length();
  const bool from_rest = clock_at_rest_;
  const bool to_rest = e.dynamics.transition == TransitionMode::ExactStop || e.dynamics.exact_stop_this_block;
  clock_at_rest_ = to_rest;
  if (!e.rapid) {
    if (e.feed_mm_s <= 0) return;
    // A straight feed move from rest to rest (G60, G9: an axis exercise's strokes) takes its
    // ramps; in continuous-path mode the feed carries on through the corners: length / F.
    double t = length / e.feed_mm_s;
    if (from_rest && to_rest && e.kind == ElementKind::Line) {
      const ChordLimits l = chord_limits(e, length);
      if (l.v > 0 && std::isfinite(l.v) && l.a > 0 && std::isfinite(l.a)) t = rest_to_rest_s(length, l.v, l.a, l.j);
    }
    nominal_time_s_ += t;
    least_time_s_ += length / e.feed_mm_s;
    if (tools_.has_tool()) cutting_time_s_ += t;  // a tool active (not T0): cutting
    return;
  }
  // A rapid move (posts write their approach as separate G0 blocks, each from rest to rest; a
  // blended chain takes less, never less than at its top speed throughout).
  const ChordLimits l = chord_limits(e, length);
  if (!(l.v > 0) || !std::isfinite(l.v)) return;
  nominal_time_s_ += l.a > 0 && std::isfinite(l.a) ? rest_to_rest_s(length, l.v, l.a, l.j) : length / l.v;
  least_time_s_ += length / l.v;
}

Interpreter::ChordLimits Interpreter::chord_limits(const PathElement& e, double length) const {
  // Along the move's chord u each axis i bounds the path to v_i/|u_i|, a_i/|u_i| (and under SOFT
  // j_i/|u_i| besides the path jerk), with the G0 or SOFT factors, the dynamic group and
  // ACC/VELOLIM/JERKLIM, as the planner's element limits (motion/element_dynamics.cpp) take them;
  // a feed move also by F.
  if (length <= 0) return {};
  const Eigen::Vector3d u = (e.curve->end() - e.curve->start()) / length;  // length: path_length()
  const machine::DynamicGroupFactors& group = profile_.dynamic_groups[static_cast<size_t>(e.dynamics.group)];
  const bool soft = e.dynamics.profile == AccelProfile::Soft;
  const double accel_factor = e.rapid ? profile_.g0_accel_factor : (soft ? profile_.soft_accel_factor : 1.0);
  const double jerk_factor = e.rapid ? profile_.g0_jerk_factor : 1.0;
  double v = e.rapid ? std::numeric_limits<double>::infinity() : e.feed_mm_s, a = std::numeric_limits<double>::infinity();
  double j = soft ? profile_.path_jerk_mm_s3 * group.max_path_jerk * jerk_factor : 0.0;
  for (size_t i = 0; i < 3 && i < profile_.axes.size(); ++i) {
    const double t = std::abs(u[static_cast<Eigen::Index>(i)]);
    if (t < 1e-12) continue;
    const auto& axis = profile_.axes[i];
    v = std::min(v, axis.max_velocity_mm_s * e.dynamics.limits.velocity[i] / t);
    a = std::min(a, axis.max_accel_mm_s2 * group.max_ax_accel * e.dynamics.limits.accel[i] * accel_factor / t);
    if (soft) j = std::min(j, axis.max_jerk_mm_s3 * group.max_ax_jerk * e.dynamics.limits.jerk[i] * jerk_factor / t);
  }
  for (const ExtraAxisMove& m : e.extra_axes) {  // each at its own rapid limits
    const double t = std::abs(m.travel) / length;
    if (t < 1e-12 || m.axis < 0 || static_cast<size_t>(m.axis) >= profile_.extra_axes.size()) continue;
    const auto& axis = profile_.extra_axes[static_cast<size_t>(m.axis)];
    v = std::min(v, axis.max_velocity_mm_s / t);
    a = std::min(a, axis.max_accel_mm_s2 * group.max_ax_accel * accel_factor / t);
    if (soft) j = std::min(j, axis.max_jerk_mm_s3 * group.max_ax_jerk * jerk_factor / t);
  }
  return {v, a, j};
}

}  // namespace drycut::interp
