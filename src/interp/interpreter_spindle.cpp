// The spindle speed: S and the G group 15 rules (G96 constant cutting speed and its ends, LIMS,
// feed type and speed mode in one block; docs/controller-state.md "Constant cutting rate"), the
// speed a block runs at, the programmable limits G25 S / G26 S, the dwell in spindle revolutions
// G4 S / G4 S<n>= (Fundamentals, "Programmable spindle speed limitation (G25, G26)" and "Dwell
// time (G4)"), the speeds $P_S / $AA_S read back and SETMS. The run-up wait (MD35500) is
// interpreter_spindle_run_up.cpp.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <cstdio>
#include <string>

#include "interp/constant_cutting_speed.hpp"
#include "interp/interpreter.hpp"
#include "interp/interpreter_block.hpp"

namespace drycut::interp {

using parser::AddressWord;
using namespace detail;

namespace {

std::string rpm_text(double rpm) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", rpm);
  return buf;
}

}  // namespace

void Interpreter::set_speed_limit(const BlockContext& ctx, const AddressWord& a) {
  // The S of a G25/G26 block is the limit, not a speed; it stays until the next G25/G26 S.
  (ctx.speed_limit == 25 ? spindle_min_rpm_ : spindle_max_rpm_) = a.value;
}

double Interpreter::within_g25_g26(double rpm) const {
  // A standing spindle (S0) is not raised to the lower limit.
  if (spindle_max_rpm_ > 0 && rpm > spindle_max_rpm_) return spindle_max_rpm_;
  if (spindle_min_rpm_ > 0 && rpm > 0 && rpm < spindle_min_rpm_) return spindle_min_rpm_;
  return rpm;
}

bool Interpreter::ends_constant_cutting_speed(const parser::Block& block) {
  // One pass over the block's G words (most blocks of a CAM program have none): runs per block.
  for (const auto& g : block.g)
    switch (g.code) {
      case 93: case 94: case 95: case 97: case 971: case 972: case 973: return true;
      default: break;
    }
  return false;
}

void Interpreter::note_group15_change(BlockContext& ctx, bool was_g96, FeedMode feed_before, double frozen_rpm) {
  // Two changes the manuals state but a programmer easily misses, named (warning 990019): a feed
  // type G93/G94/G95 after G96 ends it (the spindle keeps the speed it has, which may be the one
  // at a far tool-change position), and G97/G973 without G96 before it select feed per
  // revolution, so an F meant per minute (a Fanuc habit: G97 S8000 M3) becomes mm/rev.
  const bool g97 = ctx.block.has_g(97) || ctx.block.has_g(973);
  if (was_g96 && !state_.constant_cutting_speed && !g97 && !ctx.block.has_g(971) && !ctx.block.has_g(972) &&
      state_.spindle != SpindleState::Stopped) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "the feed type ends G96 (the same G group 15): the spindle keeps %.0f rev/min",
                  frozen_rpm);
    warn_once(ctx, 990019, buf, 0);
  } else if (!was_g96 && g97 && !ctx.block.has_g(95) && feed_before != FeedMode::PerRevolution &&
             state_.feed_mode == FeedMode::PerRevolution) {  // (G95 G97 in one block says it itself)
    warn_once(ctx, 990019, std::string(ctx.block.has_g(97) ? "G97" : "G973") +
                               " selects feed per revolution (as G95): F is now mm/rev", 0);
  }
}

void Interpreter::combine_feed_type_and_speed_mode(BlockContext& ctx) {
  // G93/G94/G95 and G96/G961/G962/G97/G971/G972/G973 are all G group 15: in one block
  // (`G96 S200 M4 G95 F0.25`, `G94 G97 S1000`) the programmer means the feed type of the one and
  // the spindle mode of the other, and that is what drycut takes. Where the two disagree (G94
  // beside G96 or G97, which imply feed per revolution; G95 beside G961/G971, which imply it per
  // minute) it says so: the manuals found do not say which of two codes of one group the control
  // takes.
  int feed = 0, speed = 0;
  for (const auto& g : ctx.block.g) {
    if (g.code == 93 || g.code == 94 || g.code == 95) feed = static_cast<int>(g.code);
    if (g.code == 96 || g.code == 961 || g.code == 962 || g.code == 97 || g.code == 971 || g.code == 972 ||
        g.code == 973)
      speed = static_cast<int>(g.code);
  }
  if (feed == 0 || speed == 0) return;
  state_.apply_code("G" + std::to_string(speed));
  state_.apply_code("G" + std::to_string(feed));  // the feed type; it also ends G96 ...
  state_.constant_cutting_speed = speed == 96 || speed == 961 || speed == 962;  // ... which the other sets
  state_.lims_acts = speed == 96 || speed == 961 || speed == 962 || speed == 97;
  const bool per_revolution = speed == 96 || speed == 97 || speed == 973;
  const bool per_minute = speed == 961 || speed == 971;
  if ((per_revolution && feed != 95) || (per_minute && feed != 94))
    warn_once(ctx, "G" + std::to_string(speed) + " with G" + std::to_string(feed) + " in one block (both G group 15): "
                   "drycut takes the feed type of G" + std::to_string(feed) + " and the spindle speed mode of G" +
                   std::to_string(speed), 0);
}

void Interpreter::apply_speed_limit_lims(BlockContext& ctx, const AddressWord& a) {
  // LIMS= the master spindle's limit; LIMS[n]= (address LIMS<n>) spindle n's, which drycut keeps
  // only for the master (the others' speeds are not simulated).
  if (a.value < 0) raise(ctx, 14820, a.name + " must not be negative", a.column);
  const std::string_view n = std::string_view(a.name).substr(4);
  if (!n.empty() && std::stoi(std::string(n)) != master_spindle_) {
    warn_once(ctx, "LIMS[" + std::string(n) + "] (the speed limit of spindle " + std::string(n) +
                       ", not the master spindle: not simulated)", a.column);
    return;
  }
  state_.spindle_speed_limit = a.value;
}

double Interpreter::lims_ceiling() const {
  return state_.lims_acts && state_.spindle_speed_limit > 0 ? state_.spindle_speed_limit : 0.0;
}

double Interpreter::within_lims(const BlockContext& ctx, double rpm) {
  // LIMS limits G97's speed too (Fundamentals, LIMS: "active if G96, G961 and G97 are active").
  const double ceiling = lims_ceiling();
  if (ceiling <= 0 || rpm <= ceiling) return rpm;
  warn_once(ctx, kValueLimited, "S" + rpm_text(rpm) + " above LIMS: limited to " + rpm_text(ceiling) + " rpm", 0);
  return ceiling;
}

double Interpreter::g96_speed_ceiling() const {
  // Under G96 the speed may rise up to MD35100, LIMS and the G26 limit, whichever is lowest (LIMS
  // acts under every G96 form; read directly, so that the G96 speed a ramp leaves from is right
  // after G95 has already ended G96 in the state).
  double max_rpm = profile_.max_spindle_speed_rpm;
  if (state_.spindle_speed_limit > 0) max_rpm = std::min(max_rpm, state_.spindle_speed_limit);
  if (spindle_max_rpm_ > 0) max_rpm = std::min(max_rpm, spindle_max_rpm_);
  return max_rpm;
}

double Interpreter::limit_to_g25_g26(const BlockContext& ctx, double rpm, bool constant_cutting_speed) {
  const double limited = within_g25_g26(rpm);
  if (limited == rpm) return rpm;
  const bool above = limited < rpm;
  // Under G96 the speed changes with every block: one warning per limit, not per speed.
  const std::string what = (constant_cutting_speed ? std::string("G96 spindle speed") : "S" + rpm_text(rpm)) +
                           (above ? " above the G26 limit" : " below the G25 limit") + ": limited to " +
                           rpm_text(limited) + " rpm";
  warn_once(ctx, kValueLimited, what, 0);
  return limited;
}

double Interpreter::dwell_in_revolutions(const BlockContext& ctx, const AddressWord& s) {
  double rpm = 0.0;
  if (const int n = numbered_spindle(s.name); n > 0 && n != master_spindle_) {
    // Another spindle: its programmed speed (S<n>=), which drycut keeps but does not simulate.
    const auto it = other_spindles_.find(n);
    if (it == other_spindles_.end() || it->second.rpm <= 0 || !it->second.turning()) {
      warn_once(ctx, "G4 " + s.name + "=: the speed of spindle " + std::to_string(n) +
                         " is not known to drycut (dwell taken as 0 s)", s.column);
      return 0.0;
    }
    rpm = it->second.rpm;
  } else {
    rpm = spindle_speed(ctx);
    if (rpm <= 0) raise(ctx, 12160, "G4 S needs a turning spindle", s.column);
  }
  const double seconds = s.value * 60.0 / rpm;
  if (!(seconds >= 0 && seconds <= kMaxDwellS)) raise(ctx, 12160, "dwell time must be 0..999999.999 s", s.column);
  return seconds;
}

void Interpreter::warn_working_area(const BlockContext& ctx) {
  // G25/G26 with axis words limit the working area (WALIMON): a setting, not a motion.
  for (const AddressWord& a : ctx.block.addresses)
    if (axis_index(a.name) >= 0 || extra_axes_.index(a.name) >= 0 || is_axis_letter_name(a.name))
      warn_once(ctx, "G" + std::to_string(ctx.speed_limit) + " " + a.name + " (working area limitation)", a.column);
}

// G4: F<seconds>, S<revolutions> of the master or S<n>=<revolutions> of spindle n.
PathElement Interpreter::dwell_element(BlockContext& ctx) {
  PathElement e = element_template(ctx, ElementKind::Dwell);
  const AddressWord* f = ctx.block.find_address("F");
  const AddressWord* s = nullptr;  // S or S<n>=: revolutions of the master or of spindle n
  for (const AddressWord& a : ctx.block.addresses)
    if (a.name == "S" || numbered_spindle(a.name) > 0) s = &a;
  if (f) {
    if (f->value < 0 || f->value > kMaxDwellS)
      raise(ctx, 12160, "dwell time must be 0..999999.999 s", f->column);
    e.dwell_s = f->value;
  } else if (s) {
    e.dwell_s = dwell_in_revolutions(ctx, *s);
  } else {
    raise(ctx, 12080, "G4 needs F<seconds> or S<revolutions>");
  }
  e.label = "G4";
  return e;
}

void Interpreter::apply_cutting_speed(BlockContext& ctx, const AddressWord& svc) {
  // SVC (Fundamentals, "Cutting rate (SVC)"): the speed is S = SVC / (2 * pi * r) with r the
  // radius of the active cutting edge; SVC in m/min (ft/min on an inch machine). It stays in
  // force (a new tool or edge gives a new S) until an S is programmed.
  if (svc.value < 0) raise(ctx, 12160, "SVC must not be negative", svc.column);
  state_.cutting_speed_svc = svc.value;
  speed_from_cutting_speed(ctx, svc.column);
}

void Interpreter::speed_from_cutting_speed(const BlockContext& ctx, uint32_t column) {
  if (state_.cutting_speed_svc <= 0) return;
  const double radius_mm = tools_.offsets().radius_mm;
  if (radius_mm <= 0) {
    warn_once(ctx, "SVC= without a tool radius (no active cutting edge or radius 0): spindle speed unchanged", column);
    return;
  }
  state_.spindle_rpm = std::min(cutting_speed_mm_min(state_.cutting_speed_svc) / (2.0 * std::numbers::pi * radius_mm),
                                profile_.max_spindle_speed_rpm);
}

void Interpreter::set_master_spindle(const BlockContext& ctx, const parser::CommandWord& c) {
  // SETMS(n): spindle n becomes the master; SETMS: the one of MD20090 again (Fundamentals,
  // "Spindle speed S, direction of rotation"). The old master keeps its speed and direction as
  // spindle n; the new one brings its own.
  int n = profile_.master_spindle;
  if (!c.args.empty()) {
    const auto* v = std::get_if<double>(&c.args[0]);
    if (!v || *v < 1 || *v > 99 || *v != std::floor(*v)) {
      warn_once(ctx, "SETMS: not a spindle number (the master spindle is unchanged)", c.column);
      return;
    }
    n = static_cast<int>(*v);
  }
  if (n == master_spindle_) return;
  // Each spindle keeps its own run-up: the new master brings the ramp it is on (or came to).
  // Under G96 the former master keeps the speed it turns at, and S stays the cutting speed, which
  // the new master takes on (Function Manual V1, "Master spindle switchover with G96").
  const bool g96 = state_.constant_cutting_speed;
  const double leaving_rpm = g96 ? std::abs(actual_spindle_speed(0)) : state_.spindle_rpm;
  other_spindles_[master_spindle_] = OtherSpindle{leaving_rpm, state_.spindle, spindle_command_, run_up_, spindle_angle_};
  const auto it = other_spindles_.find(n);
  OtherSpindle next;
  if (it == other_spindles_.end()) {
    next = OtherSpindle{0.0, SpindleState::Stopped, SpindleCommand{SpindleState::Stopped, 0.0, false, n}, SpindleRunUp{}};
  } else {
    next = it->second;
    other_spindles_.erase(it);
  }
  state_.spindle_rpm = next.rpm;  // under G96 unused until a G97 freezes the new master's speed
  state_.spindle = next.state;
  spindle_angle_ = next.angle_deg;  // each spindle keeps its angle
  master_spindle_ = n;
  become_master_run_up(next.command, next.run_up);
}

double Interpreter::programmed_spindle_speed(int spindle) const {
  if (spindle == 0 || spindle == master_spindle_)
    return state_.constant_cutting_speed ? state_.cutting_speed : state_.spindle_rpm;
  const auto it = other_spindles_.find(spindle);
  return it == other_spindles_.end() ? 0.0 : it->second.rpm;
}

int Interpreter::spindle_direction(int spindle) const {
  SpindleState state = state_.spindle;
  if (spindle != 0 && spindle != master_spindle_) {
    const auto it = other_spindles_.find(spindle);
    state = it == other_spindles_.end() ? SpindleState::Stopped : it->second.state;
  }
  switch (state) {
    case SpindleState::Clockwise: return 3;
    case SpindleState::CounterClockwise: return 4;
    case SpindleState::Stopped: break;
  }
  return 5;
}

double Interpreter::actual_spindle_speed(int spindle) const {
  // $AA_S reads the set speed at once, not the speed on the run-up ramp (the path's wait for it
  // is timed by wait_for_spindle_speed); M5 and SPOS stop it. The sign follows the direction.
  const bool master = spindle == 0 || spindle == master_spindle_;
  SpindleState state = state_.spindle;
  if (!master) {
    const auto it = other_spindles_.find(spindle);
    if (it == other_spindles_.end()) return 0.0;
    state = it->second.state;
  }
  if (state == SpindleState::Stopped) return 0.0;
  double rpm = programmed_spindle_speed(spindle);
  if (master && !state_.constant_cutting_speed) {
    // The set speed within LIMS, G26/G25 and MD35100, as spindle_speed() limits it.
    if (lims_ceiling() > 0) rpm = std::min(rpm, lims_ceiling());
    rpm = std::min(within_g25_g26(rpm), profile_.max_spindle_speed_rpm);
  } else if (master) {
    // G96: S is the cutting speed; the spindle turns at what it gives at the diameter it was
    // last set for (the last cut's end: G0 does not change it), as spindle_speed() plans it.
    rpm = g96_set_speed(g96_speed_position_, cutting_speed_mm_min(state_.cutting_speed));
  }
  return state == SpindleState::CounterClockwise ? -rpm : rpm;
}

double Interpreter::g96_set_speed(const Eigen::Vector3d& machine_position, double cutting_speed_mm_min) const {
  const Eigen::Vector3d tip = state_.frames.total(false).to_inner(machine_position - length_applied_);
  const double x = tip[state_.cutting_speed_axis];
  return constant_cutting_speed_rpm(cutting_speed_mm_min, x, x, spindle_min_rpm_, g96_speed_ceiling());
}

void Interpreter::apply_spindle_speed(BlockContext& ctx, const AddressWord& a) {
  // S, or S<n>= the speed of spindle n (Fundamentals, "Spindle speed S"): the master's is S.
  if (ctx.dwell) return;  // G4 S<rev>, G4 S2=<rev>
  if (a.value < 0) raise(ctx, 12160, a.name + " must not be negative", a.column);
  if (const int spindle = numbered_spindle(a.name); spindle > 0 && spindle != master_spindle_) {
    // Kept for G4 S<n>= (dwell in that spindle's revolutions) and for SETMS(n).
    if (!ctx.speed_limit) other_spindles_[spindle].rpm = a.value;
    return;
  }
  if (ctx.speed_limit) {
    set_speed_limit(ctx, a);
    return;
  }
  // Under G96 S is the cutting speed, kept apart from the speed in rev/min: G97 freezes the speed
  // without losing it, and a later G96 without S takes it up again (Fundamentals, "Constant
  // cutting rate": "if G96 is selected again, the entry is optional").
  (state_.constant_cutting_speed ? state_.cutting_speed : state_.spindle_rpm) = a.value;
  state_.cutting_speed_svc = 0.0;  // S and SVC replace each other
}

int Interpreter::numbered_spindle(std::string_view name) {
  if (name.size() < 2 || name[0] != 'S') return 0;
  int n = 0;
  for (size_t i = 1; i < name.size(); ++i) {
    if (name[i] < '0' || name[i] > '9' || n > 99) return 0;
    n = n * 10 + (name[i] - '0');
  }
  return n;
}

double Interpreter::cutting_speed_mm_min(double speed) const {
  // G96 S and SVC are m/min, ft/min under G70/G700 (Fundamentals, G96: "m/min (for G71/G710)
  // or ft/min (for G70/G700)").
  return speed * 1000.0 * (state_.inch ? 0.3048 : 1.0);
}

double Interpreter::spindle_speed(const BlockContext& ctx, const Eigen::Vector3d* chord) {
  // G331/G332 tap with the spindle in position control (SPOS before, no M3/M4): the speed is
  // the S programmed, the direction the sign of the lead (Fundamentals, "Tapping without
  // compensating chuck (G331, G332)").
  const bool tapping = state_.motion == MotionMode::Tapping || state_.motion == MotionMode::TappingRetract;
  if (state_.spindle == SpindleState::Stopped && !tapping) return 0.0;
  if (!state_.constant_cutting_speed || tapping) {
    // A speed above MD35100 SPIND_VELO_LIMIT is limited to it (the control limits the set-point);
    // the warning only where the speed times the path (G95, threads, tapping). G331/G332 under
    // G96 tap at the S last written, in rev/min (CYCLE84 sets its SST so after its SPOS).
    const double s = state_.constant_cutting_speed ? state_.cutting_speed : state_.spindle_rpm;
    const double rpm = limit_to_g25_g26(ctx, within_lims(ctx, s), false);
    if (rpm > profile_.max_spindle_speed_rpm) {
      if (state_.feed_mode != FeedMode::PerRevolution && !state_.thread_mode()) return profile_.max_spindle_speed_rpm;
      const std::string what = "S" + std::to_string(static_cast<long>(rpm)) +
                               " above the spindle's maximum (MD35100): limited to " +
                               std::to_string(static_cast<long>(profile_.max_spindle_speed_rpm)) + " rpm";
      warn_once(ctx, kValueLimited, what, 0);
      return profile_.max_spindle_speed_rpm;
    }
    return rpm;
  }
  // G96: S is the cutting speed at the tool; the speed follows the diameter 2|x| (work
  // coordinates; x the SCC axis, default the transverse axis of MD20100) over the block, limited
  // by LIMS, G26 and MD35100 above and G25 below (constant_cutting_speed.hpp).
  // The first G96 needs a cutting speed (Function Manual V1: alarm 10900); checked at the first
  // cut, as the S may follow in the next block.
  if (chord && state_.cutting_speed <= 0)
    raise(ctx, 10900, "G96/G961/G962 without S, and no cutting speed programmed before");
  const double speed_mm_min = cutting_speed_mm_min(state_.cutting_speed);
  // Without a chord (G4 S, G97's frozen speed, a corner's feed) the speed the spindle has: the one
  // set for the last cut's end, which a G0 since has not changed (Fundamentals, "Constant cutting
  // rate": "G0 does not change the speed").
  const Frame& frame = block_frame(ctx);
  const Eigen::Vector3d tip = (chord ? position_ : g96_speed_position_) - length_applied_;
  const double x0 = frame.to_inner(tip)[state_.cutting_speed_axis];
  const double x1 = chord ? frame.to_inner(tip + *chord)[state_.cutting_speed_axis] : x0;
  const double max_rpm = g96_speed_ceiling();
  for (const double x : {x0, x1}) {  // the G25/G26 warnings where the ends of the block need them
    const double rpm = std::abs(x) > 1e-9 ? speed_mm_min / (std::numbers::pi * 2.0 * std::abs(x)) : max_rpm;
    limit_to_g25_g26(ctx, state_.spindle_speed_limit > 0 ? std::min(rpm, state_.spindle_speed_limit) : rpm, true);
  }
  return constant_cutting_speed_rpm(speed_mm_min, x0, x1, spindle_min_rpm_, max_rpm);
}

// G331/G332 interpolate the lead axis with the spindle in position control: the axis moves one
// lead per revolution, so it accelerates as the spindle does times the lead, and the spindle's
// acceleration in position control is MD35210 GEAR_STEP_POSCTRL_ACCEL (docs/controller-state.md
// "Feeds", G331/G332). The element's ACC factor of the lead axis is lowered so that the
// planner's acceleration of that axis (MD32300 x dynamic group x SOFT factor x ACC) is at most
// lead x MD35210; the braking at the tapping depth and the run-up of G332 (the reversal) follow.
void Interpreter::limit_tapping_acceleration(PathElement& e) const {
  const double spindle = profile_.spindle_posctrl_accel_rev_s2;
  const int k = state_.thread_lead_axis;
  if (!(spindle > 0) || !(state_.thread_lead_mm > 0) || k < 0 || k > 2) return;
  const size_t axis = static_cast<size_t>(k);
  const double axis_accel = machine::axis_mode_accel_mm_s2(profile_, axis, static_cast<size_t>(state_.dynamic_group),
                                                           false, state_.accel == AccelProfile::Soft);
  if (!(axis_accel > 0)) return;
  float& factor = e.dynamics.limits.accel[axis];
  factor = std::min(factor, static_cast<float>(state_.thread_lead_mm * spindle / axis_accel));
}

}  // namespace drycut::interp
