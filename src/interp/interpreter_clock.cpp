// The interpreter's clock: the nominal time of what it emitted (path length over the feed,
// rapid moves from rest to rest, dwells, tool changes), the part of it at feed with a tool active
// (tool action time), and the waits of a program that polls the clock. Timers and clock
// variables a program reads, and the spindle run-up's wait, use it while the planner is still
// behind the interpreter (docs/controller-state.md "Clock, run-time counters ...").
#include <algorithm>
#include <cmath>

#include "interp/interpreter.hpp"
#include "interp/interpreter_block.hpp"

namespace drycut::interp {

double Interpreter::poll_clock(uint64_t line) {
  if (line != line_at_poll_) {
    const double worked = nominal_time_s_ - waited_s_;  // motion and dwells, not the waits
    if (worked == worked_at_poll_) clock_wait_s_ += profile_.ipo_cycle_s;
    worked_at_poll_ = worked;
    line_at_poll_ = line;
  }
  return nominal_time_s();
}

void Interpreter::emit_clock_wait(const BlockContext& ctx) {
  // The polls since the last element: the program waited for the clock before this block.
  PathElement e = element_template(ctx, ElementKind::Dwell);
  e.dwell_s = clock_wait_s_;
  e.label = "waiting for the clock";
  waited_s_ += clock_wait_s_;
  clock_wait_s_ = 0.0;
  emit(std::move(e));
}

void Interpreter::add_nominal_time(const PathElement& e) {
  // An estimate of the planned time (feed moves without ramps or corners, rapid moves from rest
  // to rest): enough for timers a program reads while the planner is still behind the
  // interpreter, and for the spindle run-up that G0 moves overlap.
  if (e.kind == ElementKind::Dwell) {
    nominal_time_s_ += e.dwell_s;
    return;
  }
  if (e.kind == ElementKind::ToolChange) {
    nominal_time_s_ += profile_.tool_change_time_s;
    return;
  }
  if (!e.is_motion() || !e.curve) return;
  const double length = e.curve->length();
  if (!e.rapid) {
    if (e.feed_mm_s <= 0) return;
    nominal_time_s_ += length / e.feed_mm_s;
    if (tools_.has_tool()) cutting_time_s_ += length / e.feed_mm_s;  // a tool active (not T0): cutting
    return;
  }
  // A rapid move (posts write their approach as separate G0 blocks, each from rest to rest):
  // the slowest axis's velocity and G0 acceleration, a trapezoid or, when too short, a triangle.
  double v = 0, a = 0;
  for (const auto& axis : profile_.axes) {
    v = v > 0 ? std::min(v, axis.max_velocity_mm_s) : axis.max_velocity_mm_s;
    const double accel = axis.max_accel_mm_s2 * profile_.g0_accel_factor;
    a = a > 0 ? std::min(a, accel) : accel;
  }
  if (v <= 0) return;
  if (a <= 0) nominal_time_s_ += length / v;
  else nominal_time_s_ += length >= v * v / a ? length / v + v / a : 2.0 * std::sqrt(length / a);
}

}  // namespace drycut::interp
