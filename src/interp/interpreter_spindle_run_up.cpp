// The spindle run-up and the path's wait for it (Function Manual S1 Spindles, "Spindle in
// setpoint range"; MD35500 SPIND_ON_SPEED_AT_IPO_START, MD35150 SPIND_DES_VELO_TOL, MD35200
// GEAR_STEP_SPEEDCTRL_ACCEL; docs/controller-state.md "Spindle run-up").
//
// Model: every spindle has its own ramp. A programmed change of a spindle's command (S, M3/M4/M5,
// G96/G97, SETMS, SPOS) starts a ramp at MD35200 from the speed its last ramp had come to, to the
// new set speed (signed: M4 negative). After a change of the master's command the first path
// block with feed waits until the master's actual speed is within MD35150 of the set speed; G0
// blocks run meanwhile. Under G96 the set speed is the one at the start of that first cut, and
// from then on the spindle follows the set speed along the diameter of each cut, while G0 leaves
// it as it is (G97 then freezes the speed of the last cut's end, which the spindle already has:
// no wait).
//
// Timing: the interpreter knows only its nominal clock (interpreter_clock.cpp), so it decides
// whether a wait may be due (ramp time into the set range > nominal time since the change) and
// emits a dwell "waiting for the spindle speed" with that estimate. The ramp's first element
// carries its id (PathElement::run_up_start) and the dwell the same id with the ramp time
// (run_up_wait, run_up_s): the planner, which knows when that element started, makes the dwell
// max(0, start + ramp time − its clock). A ramp SETMS brings back (begun under another master)
// has no id: its estimate stands.
#include <algorithm>
#include <cmath>
#include <utility>

#include "interp/interpreter.hpp"
#include "interp/interpreter_block.hpp"

namespace drycut::interp {

namespace {

double with_direction(SpindleState state, double rpm) {  // M4 turns negative
  return state == SpindleState::CounterClockwise ? -rpm : rpm;
}

}  // namespace

Interpreter::SpindleRunUp Interpreter::next_run_up(const SpindleCommand& old, const SpindleRunUp& ramp,
                                                   double set_rpm) const {
  // Where the old ramp has come to: on its way at MD35200, or, under G96 after its first cut,
  // at the old set speed at the tool's diameter now.
  double speed;
  if (ramp.follows_set_speed && old.constant_cutting_speed && old.state != SpindleState::Stopped) {
    speed = with_direction(old.state, g96_set_speed(g96_speed_position_, old.value));
  } else {
    const double accel_rpm_s = profile_.spindle_speedctrl_accel_rev_s2 * 60.0;
    const double rise = ramp.to_rpm - ramp.from_rpm;
    const double reached = std::min(std::abs(rise), accel_rpm_s * (nominal_time_s_ - ramp.since_s));
    speed = ramp.from_rpm + std::copysign(reached, rise);
  }
  SpindleRunUp next = standing_run_up();
  next.from_rpm = speed;
  next.to_rpm = set_rpm;
  return next;
}

Interpreter::SpindleRunUp Interpreter::standing_run_up() const {
  SpindleRunUp r;
  r.since_s = nominal_time_s_;
  r.since_least_s = least_time_s_;
  return r;
}

void Interpreter::note_spindle_change() {
  // A G96 speed that follows the diameter is no programmed change (the command is unchanged).
  // Outside G96 the set speed (a new LIMS or G26 below S changes it too).
  const double value = state_.constant_cutting_speed ? cutting_speed_mm_min(state_.cutting_speed)
                                                     : std::abs(actual_spindle_speed(0));
  const SpindleCommand now{state_.spindle, value, state_.constant_cutting_speed, master_spindle_};
  if (now != spindle_command_) {
    run_up_ = next_run_up(spindle_command_, run_up_, 0.0);  // from the speed it has
    g96_speed_position_ = position_;                        // a new G96 speed is set for here
    run_up_.to_rpm = actual_spindle_speed(0);
    run_up_.pending = profile_.spindle_on_speed_at_ipo_start > 0;
    run_up_.id = ++run_up_count_;
    run_up_mark_ = run_up_.id;
    spindle_command_ = now;
  }
  for (auto& [n, s] : other_spindles_) {  // S2= M2=3 ...: their own ramps (for a later SETMS)
    const SpindleCommand c{s.state, s.rpm, false, n};
    if (c == s.command) continue;
    s.run_up = next_run_up(s.command, s.run_up, actual_spindle_speed(n));
    s.command = c;
  }
}

void Interpreter::settle_spindles_at_stop() {
  // M0/M1 wait for the operator, far longer than any ramp (a dry run counts no time for it): the
  // spindles reach their set speeds meanwhile, a braking one stands (M5 M0 then S2000 M3 runs up
  // from rest, a cut after the stop does not wait for a ramp begun before it).
  auto settle = [this](SpindleRunUp& ramp) {
    ramp.from_rpm = ramp.to_rpm;
    ramp.since_s = nominal_time_s_;
    ramp.since_least_s = least_time_s_;
    ramp.pending = false;
  };
  settle(run_up_);
  for (auto& [n, s] : other_spindles_) settle(s.run_up);
  master_braking_ = {};
}

void Interpreter::become_master_run_up(const SpindleCommand& command, const SpindleRunUp& ramp) {
  // SETMS: the new master's ramp, begun under the old master, is what the next cut waits for
  // (nothing once it is in range); its start is not marked for the planner.
  spindle_command_ = command;
  run_up_ = ramp;
  run_up_.pending = profile_.spindle_on_speed_at_ipo_start > 0;
  run_up_.id = 0;
}

void Interpreter::wait_for_spindle_speed(const PathElement& next) {
  // Called for the first element with feed after a change (G0 does not wait: its block runs
  // while the spindle comes up, drycut's reading of MD35500). A stopped spindle holds nothing
  // back.
  if (recorder_.active()) return;  // a contour recorded without moving: the first real cut waits
  run_up_.pending = false;
  if (std::exchange(spindle_left_to_changer_, false) && state_.spindle != SpindleState::Stopped)
    diagnostics_.warn(detail::kNotModelled,
                      "the tool change (M6) stopped the spindle and no S, M3 or M4 came since: drycut restarts it at the "
                      "last speed for this cut (whether the machine's tool-change cycle does is the builder's)",
                      {next.source.file_name(), next.source.line, 0}, next.source.text);
  if (state_.constant_cutting_speed && state_.spindle != SpindleState::Stopped && next.curve) {
    // G96: the set speed where the cut starts, not where G96 was programmed (a tool-change point
    // far out gives a low speed, the centre the LIMS speed).
    run_up_.to_rpm = with_direction(state_.spindle, g96_set_speed(next.curve->at(0.0).position,
                                                                  cutting_speed_mm_min(state_.cutting_speed)));
    run_up_.follows_set_speed = true;
  }
  if (run_up_.to_rpm == 0.0) return;
  const double tolerance = profile_.spindle_des_velo_tol * std::abs(run_up_.to_rpm);
  const double ramp_s = std::max(0.0, std::abs(run_up_.to_rpm - run_up_.from_rpm) - tolerance) /
                        (profile_.spindle_speedctrl_accel_rev_s2 * 60.0);
  // A ramp the planner times (marked) may still be going on unless even the least time of the
  // moves since covers it (a blended G0 chain is quicker than the estimate's moves from rest to
  // rest); the planner's wait may then come out 0. A ramp SETMS brought back has only the estimate.
  const double estimate_s = ramp_s - (nominal_time_s_ - run_up_.since_s);
  const double longest_s = ramp_s - (least_time_s_ - run_up_.since_least_s);
  if ((run_up_.id != 0 ? longest_s : estimate_s) <= 1e-9) return;
  PathElement e;
  e.kind = ElementKind::Dwell;
  e.source = next.source;
  e.dwell_s = std::max(0.0, estimate_s);
  if (run_up_.id != 0) {
    e.run_up_wait = run_up_.id;
    e.run_up_s = ramp_s;
  }
  e.label = "waiting for the spindle speed (MD35500)";
  emit(std::move(e));
}

double Interpreter::spindle_speed_on_ramp(int spindle) const {
  // A warm-up macro polls $AA_S until the spindle is at speed (S8000 M3 / WHILE $AA_S[1]<7900
  // ENDWHILE): each poll lets the clock run (SystemVariables::read), so the loop waits out the
  // ramp. The ramp as the run-up model has it: from its start speed at MD35200 since the change.
  const double target = actual_spindle_speed(spindle);
  const SpindleRunUp* ramp = &run_up_;
  if (spindle != 0 && spindle != master_spindle_) {
    const auto it = other_spindles_.find(spindle);
    if (it == other_spindles_.end()) return target;
    ramp = &it->second.run_up;
  }
  const double rise = target - ramp->from_rpm;
  const double reached = profile_.spindle_speedctrl_accel_rev_s2 * 60.0 * (nominal_time_s() - ramp->since_s);
  return reached >= std::abs(rise) ? target : ramp->from_rpm + std::copysign(std::max(0.0, reached), rise);
}

void Interpreter::note_spindle_programmed(const parser::Block& block) {
  // After M6: a block that programs the master spindle (S, M3/M4/M5/M19, SPOS) answers it, in
  // the tool-change block too (T1 M6 S1000 M3, whatever the order of its words).
  const bool speed = std::any_of(block.addresses.begin(), block.addresses.end(), [&](const parser::AddressWord& a) {
    return a.name == "S" || a.name == "SPOS" || numbered_spindle(a.name) == master_spindle_;
  });
  const bool function = std::any_of(block.m.begin(), block.m.end(), [&](const parser::MWord& m) {
    return ((m.code >= 3 && m.code <= 5) || m.code == 19) && (m.extension <= 0 || m.extension == master_spindle_);
  });
  if (speed || function) spindle_left_to_changer_ = false;
}

void Interpreter::note_tool_change_stops_spindle() {
  // A tool change with M6 (MD22550 = 1, a milling machine's magazine) stops and orients the tool
  // spindle for the changer: the next programmed speed, even the same S M3 again, ramps from
  // standstill after it. A turret's T (MD22550 = 0, a lathe) leaves the work spindle turning.
  if (!tools_.change_on_m_code()) return;
  spindle_left_to_changer_ = state_.spindle != SpindleState::Stopped;
  run_up_ = standing_run_up();
  spindle_command_ = SpindleCommand{SpindleState::Stopped, 0.0, false, master_spindle_};
}

}  // namespace drycut::interp
