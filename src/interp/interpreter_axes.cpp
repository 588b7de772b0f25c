// Channel axes beyond X, Y, Z: synchronized axes that move with the path (A=, C=DC(..)),
// positioning axes on their own interpolators (POS/POSA, SPOS/SPOSA; POS of X/Y/Z too), their
// feeds (FA, FGROUP) and waits (WAITP/WAITS). The rules are in extra_axes.hpp and docs/axes.md.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "interp/geometry/line_curve.hpp"
#include "interp/interpreter.hpp"
#include "interp/interpreter_block.hpp"
#include "interp/rest_to_rest.hpp"

namespace drycut::interp {

using parser::AddressWord;
using parser::AxisWord;
using parser::AxisWordKind;
using parser::ValueMode;
using namespace detail;

namespace {


std::vector<std::string> text_args(const parser::CommandWord& c) {
  std::vector<std::string> out;
  for (const auto& a : c.args)
    if (const auto* s = std::get_if<std::string>(&a)) out.push_back(*s);
    else out.push_back(parser::number_to_text(std::get<double>(a)));
  return out;
}

}  // namespace

bool Interpreter::note_extra_axis_word(BlockContext& ctx, const AddressWord& a) {
  if (const int i = extra_axes_.index(a.name); i >= 0) {
    ctx.extra_words.emplace_back(static_cast<size_t>(i), &a);
    // An axis still on its way from POSA: the block waits for it first (implicit WAITP).
    if (extra_axes_.running(a.name)) wait_for(ctx, a.name);
    return true;
  }
  if (is_axis_letter_name(a.name)) {
    warn_once(ctx, "axis " + a.name + " is not in the machine profile (its moves are not simulated)", a.column);
    return true;
  }
  if (is_orientation_word(a.name)) {
    // A block that only turns the tool takes time on the machine and none here. The same names
    // are extended addresses of axes (a second C axis, C2) on a machine without TRAORI.
    warn_once(ctx, "tool orientation A2/B2/C2, A3/B3/C3, A4..C5, or axes of these names the profile lacks "
                   "(the rotary axes' moves are not simulated)", a.column);
    return true;
  }
  return note_unknown_axis_word(ctx, a);
}

bool Interpreter::note_unknown_axis_word(BlockContext& ctx, const AddressWord& a) {
  // Words that name an axis drycut does not have: never dropped without a word (a tool-change
  // retract `G0 X1=30` that moves nothing puts every later move in the wrong place).
  const std::string_view n = a.name;
  if (machine_axis_index(n) >= 0) {
    if (ctx.home_move == 0)  // G74/G75 move it (move_to_fixed_point)
      warn_once(ctx, a.name + "= (the machine axis name of " + std::string(n.substr(0, 1)) +
                         ") outside G74/G75: the axis does not move",
                a.column);
    return true;
  }
  if (!is_extended_axis_address(n)) return false;
  warn_once(ctx, "axis " + a.name + " is not in the machine profile (its moves are not simulated)", a.column);
  return true;
}

bool Interpreter::apply_axis_command(BlockContext& ctx, const parser::CommandWord& c) {
  if (c.name == "FGROUP") {
    std::vector<std::string> names;
    for (auto& n : text_args(c)) {
      if (!n.empty() && axis_index(n) < 0 && extra_axes_.index(n) < 0 && is_unsimulated_axis_name(n))
        warn_once(ctx, "FGROUP: axis " + n + " is not in the machine profile", c.column);
      else
        names.push_back(std::move(n));
    }
    const std::string bad = extra_axes_.set_feed_group(names);
    if (!bad.empty()) raise(ctx, 12550, "FGROUP: " + bad + " is not an axis of the channel", c.column);
    return true;
  }
  if (c.name == "WAITP") {
    if (c.args.empty()) raise(ctx, 12080, "WAITP needs an axis", c.column);
    for (const auto& axis : text_args(c)) {
      if (extra_axes_.index(axis) < 0 && axis_index(axis) < 0) {
        if (!is_unsimulated_axis_name(axis)) raise(ctx, 12550, "WAITP: " + axis + " is not an axis of the channel", c.column);
        warn_once(ctx, "WAITP: axis " + axis + " is not in the machine profile", c.column);
        continue;
      }
      wait_for(ctx, axis);
    }
    return true;
  }
  if (c.name == "WAITS") {
    // WAITS: the master spindle; WAITS(n, ...): those spindles.
    const auto args = text_args(c);
    if (args.empty() || (args.size() == 1 && args[0].empty())) ctx.waits.push_back("S1");
    for (const auto& n : args)
      if (!n.empty()) ctx.waits.push_back("S" + n);
    return true;
  }
  return false;
}

void Interpreter::set_feed_reference_radius(BlockContext& ctx, const AxisWord& w) {
  // FGREF[ax]=r (Fundamentals, "Feedrate for rotary axes: FGREF"): with a rotary axis in the
  // feed group, its degrees count in the path length as the arc they make at radius r, so F
  // (mm/min) means the feed at that radius. drycut scales the axis's share of the length.
  const int i = extra_axes_.index(w.axis);
  if (i < 0 || !extra_axes_.data(static_cast<size_t>(i)).rotary) {
    if (i < 0 && axis_index(w.axis) < 0 && !names_channel_axis(w.axis))
      raise(ctx, 12550, "FGREF[" + w.axis + "]: not an axis of the channel", w.column);
    warn_once(ctx, "FGREF[" + w.axis + "] (acts on rotary axes only)", w.column);
    return;
  }
  if (!(w.value >= 0)) raise(ctx, 12160, "FGREF[" + w.axis + "] must be >= 0", w.column);
  const double radius_mm = w.value * geometry_unit();
  extra_axes_.set_feed_weight(static_cast<size_t>(i), radius_mm > 0 ? 2.0 * std::numbers::pi * radius_mm / 360.0 : 1.0);
}

void Interpreter::apply_axis_words(BlockContext& ctx) {
  // FA[ax] first: `POS[A]=30 FA[A]=600` moves A at the FA of its own block, wherever it stands.
  std::vector<const AxisWord*> words;
  words.reserve(ctx.block.axis_words.size());
  for (const AxisWord& w : ctx.block.axis_words)
    if (w.kind == AxisWordKind::AxialFeed) words.push_back(&w);
  for (const AxisWord& w : ctx.block.axis_words)
    if (w.kind != AxisWordKind::AxialFeed) words.push_back(&w);
  for (const AxisWord* word : words) {
    const AxisWord& w = *word;
    switch (w.kind) {
      case AxisWordKind::AxialFeed: {
        const int i = extra_axes_.index(w.axis);
        if (const int g = axis_index(w.axis); g >= 0) {  // the feed of POS[X] ...
          if (!(w.value > 0)) raise(ctx, 14800, "FA[" + w.axis + "] must be > 0", w.column);
          geometry_positioning_feed_[static_cast<size_t>(g)] = w.value / 60.0 * feed_unit();
          continue;
        }
        if (i < 0) {
          // An axis letter the profile lacks (as POS[A]) or a spindle (FA[SPI(1)]: the speed of
          // SPOS): valid, not modelled.
          if (!names_channel_axis(w.axis)) raise(ctx, 12550, "FA[" + w.axis + "]: not an axis of the channel", w.column);
          warn_once(ctx, "FA[" + w.axis + "] (the feed of a positioning axis or spindle drycut does not simulate)", w.column);
          continue;
        }
        if (!(w.value > 0)) raise(ctx, 14800, "FA[" + w.axis + "] must be > 0", w.column);
        const bool rotary = extra_axes_.data(static_cast<size_t>(i)).rotary;
        extra_axes_.set_positioning_feed(static_cast<size_t>(i), w.value / 60.0 * (rotary ? 1.0 : feed_unit()));
        break;
      }
      case AxisWordKind::Pos:
      case AxisWordKind::PosA: add_positioning(ctx, w); break;
      case AxisWordKind::SPos:
      case AxisWordKind::SPosA: add_spindle_positioning(ctx, w); break;
      case AxisWordKind::AccelPercent:
      case AxisWordKind::VelocityPercent:
      case AxisWordKind::JerkPercent: set_axis_limit(ctx, w); break;
      case AxisWordKind::FeedReferenceRadius: set_feed_reference_radius(ctx, w); break;
    }
  }
}

bool Interpreter::names_channel_axis(const std::string& name) const {
  // X/Y/Z, the profile's extra axes, an axis letter the profile lacks (warned where used) or a
  // spindle SP<n>: an axis-indexed word (FA[..], ACC[..]) with any other name is alarm 12550.
  return axis_index(name) >= 0 || extra_axes_.index(name) >= 0 || is_unsimulated_axis_name(name) ||
         is_spindle_axis_name(name);
}

void Interpreter::set_axis_limit(BlockContext& ctx, const AxisWord& w) {
  // ACC 1..200 % (0: off, i.e. 100 %), VELOLIM 1..100 %, JERKLIM 1..200 %, modal per axis. A
  // value outside the range is limited to it with warning 990013 (drycut does not know the
  // control's alarm for it, so it does not refuse the block).
  const char* name = w.kind == AxisWordKind::AccelPercent ? "ACC" : w.kind == AxisWordKind::VelocityPercent ? "VELOLIM" : "JERKLIM";
  const std::string word = std::string(name) + "[" + w.axis + "]";
  const int i = axis_index(w.axis);
  if (i < 0) {
    if (!names_channel_axis(w.axis)) raise(ctx, 12550, word + ": not an axis of the channel", w.column);
    warn_once(ctx, word + " (limits of an axis other than X, Y, Z are not modelled)", w.column);
    return;
  }
  const double upper = w.kind == AxisWordKind::VelocityPercent ? 100.0 : 200.0;
  double percent = w.kind == AxisWordKind::AccelPercent && w.value == 0.0 ? 100.0 : w.value;
  if (!(percent >= 1.0 && percent <= upper)) {
    percent = std::clamp(std::isnan(percent) ? 100.0 : percent, 1.0, upper);
    warn_once(ctx, kValueLimited, word + "=" + parser::number_to_text(w.value) + " outside 1 .. " +
                                      parser::number_to_text(upper) + " %, " + parser::number_to_text(percent) + " % taken",
              w.column);
  }
  AxisLimitFactors& f = state_.axis_limits;
  auto& target = w.kind == AxisWordKind::AccelPercent ? f.accel : w.kind == AxisWordKind::VelocityPercent ? f.velocity : f.jerk;
  target[static_cast<size_t>(i)] = static_cast<float>(percent / 100.0);
}

std::optional<parser::Block> Interpreter::geometry_positioning_block(const parser::Block& block,
                                                                     GeometryPositioning& mode) const {
  const auto positions_geometry = [this](const AxisWord& w) {
    return (w.kind == AxisWordKind::Pos || w.kind == AxisWordKind::PosA) && axis_index(w.axis) >= 0;
  };
  if (std::none_of(block.axis_words.begin(), block.axis_words.end(), positions_geometry)) return std::nullopt;
  const bool alone = std::none_of(block.addresses.begin(), block.addresses.end(), [this](const AddressWord& a) {
    return axis_index(a.name) >= 0 || a.name == "AP" || a.name == "RP";
  });
  const bool async = std::any_of(block.axis_words.begin(), block.axis_words.end(), [&](const AxisWord& w) {
    return positions_geometry(w) && w.kind == AxisWordKind::PosA;
  });
  mode = !alone ? GeometryPositioning::WithPath : async ? GeometryPositioning::AloneAsync : GeometryPositioning::Alone;
  parser::Block moved = block;
  moved.axis_words.clear();
  for (const AxisWord& w : block.axis_words) {
    if (positions_geometry(w)) moved.addresses.push_back(AddressWord{w.axis, w.value, w.mode, w.column});
    else moved.axis_words.push_back(w);
  }
  return moved;
}

void Interpreter::move_to_fixed_point(BlockContext& ctx) {
  // G74 X.. Z.. (reference point) / G75 FP=n X.. Z.. (fixed point n, 1..4; PGA Fundamentals,
  // "Fixed-point approach (G75)", "Reference point approach (G74)"): each axis written goes to
  // its point in machine coordinates at rapid; the values written are ignored. The points are
  // MD34100 REFP_SET_POS / MD30600 FIX_POINT_POS of the profile (default 0, warned). drycut
  // plans one rapid straight move of the carrier; frames, tool length and the compensation do
  // not act on it. Extra axes written in the block do not move (warned).
  if (spline_.active()) end_spline_run(nullptr);
  int point = 1;
  if (const AddressWord* fp = ctx.block.find_address("FP")) {
    if (ctx.home_move != 75 || !(fp->value >= 1 && fp->value <= 4) || fp->value != std::trunc(fp->value))
      raise(ctx, 12160, "FP must be 1..4 and goes with G75", fp->column);
    point = static_cast<int>(fp->value);
  }
  // G74 in a program runs the axes' referencing (Function Manual R1, "Referencing": search for
  // the cam and the zero mark at MD34020/MD34040, then MD34070), timed here as a rapid move.
  if (ctx.home_move == 74)
    warn_once(ctx, "G74 reference point approach (timed as one rapid move, not as the referencing sequence)", 0);
  Vector3d target = position_;
  for (const AddressWord& a : ctx.block.addresses) {
    const int i = std::max(axis_index(a.name), machine_axis_index(a.name));  // X or X1 (the other is -1)
    if (i < 0) {
      if (a.name != "FP" && extra_axes_.index(a.name) >= 0)
        warn_once(ctx, "G" + std::to_string(ctx.home_move) + " of axis " + a.name + " (the axis does not move)", a.column);
      continue;
    }
    const machine::AxisData& axis = profile_.axes[static_cast<size_t>(i)];
    std::optional<double> value = ctx.home_move == 74 ? axis.reference_point_mm
                                  : static_cast<size_t>(point) <= axis.fix_points_mm.size()
                                      ? std::optional<double>(axis.fix_points_mm[static_cast<size_t>(point - 1)])
                                      : std::nullopt;
    if (!value) {
      warn_once(ctx, 990007,
                (ctx.home_move == 74 ? "MD34100 REFP_SET_POS of " : "MD30600 FIX_POINT_POS[" + std::to_string(point - 1) + "] of ") +
                    axis.name + " not in the machine profile: 0 assumed",
                a.column);
      value = 0.0;
    }
    target[i] = *value;
  }
  check_limits(ctx, target);
  PathElement e = element_template(ctx, ElementKind::Line);
  e.curve = std::make_shared<geometry::LineCurve>(position_, target);
  e.rapid = true;
  e.label = "G" + std::to_string(ctx.home_move);
  position_ = target;
  emit(std::move(e));
}

void Interpreter::position_geometry_axes(BlockContext& ctx, std::vector<ExtraAxisMove> extra) {
  // POS/POSA of geometry axes alone (Fundamentals, "Traversing positioning axes"): each axis on
  // its own interpolator at FA[ax] (else MD32060 POS_AX_VELO), to its end before the block ends.
  // drycut plans one straight move whose feed lets the slowest axis arrive at its own speed,
  // without jerk limit (BRISKA) and with an exact stop at the end; POSA (the program going on
  // meanwhile) is planned as POS.
  if (spline_.active()) end_spline_run(nullptr);
  const Target programmed = target_position(ctx);
  length_applied_ = programmed.length_after;
  check_limits(ctx, programmed.machine);
  PathElement e = element_template(ctx, ElementKind::Line);
  e.curve = std::make_shared<geometry::LineCurve>(position_, programmed.machine);
  attach_extra_axes(ctx, e, std::move(extra));
  e.rapid = false;
  e.label = "POS";
  double time_s = 0.0;
  for (size_t i = 0; i < 3; ++i) {
    const double travel = std::abs(programmed.machine[static_cast<Eigen::Index>(i)] - position_[static_cast<Eigen::Index>(i)]);
    if (travel <= 0) continue;
    e.label += " " + profile_.axes[i].name;
    const double velocity = std::min(geometry_positioning_feed_[i], profile_.axes[i].max_velocity_mm_s);
    if (velocity > 0) time_s = std::max(time_s, travel / velocity);
  }
  // A move of no length (the axes already there) still needs a feed of its own.
  e.feed_mm_s = time_s > 0 ? e.curve->length() / time_s : geometry_positioning_feed_[0];
  e.dynamics.exact_stop_this_block = true;
  e.dynamics.profile = AccelProfile::Brisk;  // BRISKA, the positioning axes' default (MD32420)
  position_ = e.curve->end();
  emit(std::move(e));
}

void Interpreter::add_positioning(BlockContext& ctx, const AxisWord& w) {
  const int k = extra_axes_.index(w.axis);
  if (k < 0) {  // geometry axes are moved by position_geometry_axes
    if (!is_unsimulated_axis_name(w.axis)) raise(ctx, 12550, "POS[" + w.axis + "]: not an axis of the channel", w.column);
    warn_once(ctx, std::string(w.kind == AxisWordKind::Pos ? "POS" : "POSA") + "[" + w.axis +
                       "] (axis " + w.axis + " is not in the machine profile; it does not move)", w.column);
    return;
  }
  const size_t i = static_cast<size_t>(k);
  if (extra_axes_.running(w.axis)) wait_for(ctx, w.axis);  // programmed again while its POSA runs
  const double from = extra_axes_.position(i);
  const double travel = move_extra_axis(ctx, i, w.value, w.mode, w.column);
  const machine::AxisData& a = extra_axes_.data(i);
  PositioningMove m;
  m.axis = w.axis;
  m.travel = std::abs(travel);
  m.velocity = std::min(extra_axes_.positioning_feed(i), a.max_velocity_mm_s);
  m.accel = a.max_accel_mm_s2;
  m.block_synchronous = w.kind == AxisWordKind::Pos;
  if (!m.block_synchronous) mark_running(m, from, travel);
  ctx.positioning.push_back(std::move(m));
}

void Interpreter::add_spindle_positioning(BlockContext& ctx, const AxisWord& w) {
  // SPOS= (no number) positions the master spindle (MD20090, SETMS); every spindle takes the
  // same machine data. Each spindle's angle is followed (0 at the start, where its last SPOS left it).
  const int number = w.axis.empty() ? master_spindle_ : std::atoi(w.axis.c_str());
  const bool master = number == master_spindle_;
  const std::string name = "S" + std::to_string(number);
  if (extra_axes_.running(name)) wait_for(ctx, name);
  constexpr double kTurn = 360.0;
  // The spindle is a modulo axis in position control: DC/ACP/ACN take 0 <= v < 360, as on a
  // modulo rotary axis (16830; SPOS=400 without them is reduced like C=AC(400)).
  const bool direction = w.mode == ValueMode::Direct || w.mode == ValueMode::AbsolutePositive ||
                         w.mode == ValueMode::AbsoluteNegative;
  if (direction && !(w.value >= 0 && w.value < kTurn))
    raise(ctx, 16830, "SPOS: position " + parser::number_to_text(w.value) + " with DC/ACP/ACN outside 0 .. 360", w.column);
  const auto other = other_spindles_.find(number);
  // The master's actual speed: where its run-up has come to (an SPOS soon after S.. M3 finds it
  // below the set speed), under G96 the speed at the tool's diameter, not the S of m/min.
  const double rpm = master ? std::abs(spindle_speed_on_ramp(0)) : other != other_spindles_.end() ? other->second.rpm : 0.0;
  const bool turning = rpm > 0 && (master ? state_.spindle != SpindleState::Stopped
                                          : other != other_spindles_.end() && other->second.turning());
  const double angle = master ? spindle_angle_ : other != other_spindles_.end() ? other->second.angle_deg : 0.0;
  PositioningMove m;
  m.axis = name;
  m.velocity = profile_.spindle_posctrl_velo_rpm * kTurn / 60.0;
  m.accel = profile_.spindle_posctrl_accel_rev_s2 * kTurn;
  // From rotation (Function Manual S1 Spindles, "Positioning from rotation"): above MD35300 the
  // spindle brakes at MD35200 down to it; position control takes over at the speed it then turns
  // at (MD35300, or its own when slower), it turns on to its braking point and brakes at MD35210
  // onto the position. Where it stands when position control takes over is unknown in a dry run:
  // the position is taken half a turn beyond the braking distance (the mean over all angles).
  const auto from_rotation = [&](double turning_rpm) {
    const double posctrl_rpm = profile_.spindle_posctrl_velo_rpm;
    m.lead_time_s = std::max(0.0, turning_rpm - posctrl_rpm) / 60.0 / profile_.spindle_speedctrl_accel_rev_s2;
    m.entry_velocity = std::min(turning_rpm, posctrl_rpm) * kTurn / 60.0;
    m.velocity = m.entry_velocity;  // a slower spindle keeps its speed, it is not sped up to MD35300
    m.travel = kTurn / 2 + (m.accel > 0 ? m.entry_velocity * m.entry_velocity / (2.0 * m.accel) : 0.0);
  };
  if (w.mode == ValueMode::Incremental) {
    m.travel = std::abs(w.value);
  } else if (turning) {
    from_rotation(rpm);
  } else if (const double braking_rpm = master_braking_.from_rpm - (nominal_time_s_ - master_braking_.since_s) * 60.0 *
                                                                     profile_.spindle_speedctrl_accel_rev_s2;
             master && master_braking_.from_rpm > 0 && braking_rpm > 0) {
    from_rotation(braking_rpm);  // still turning down after M5: from the speed it has come down to
  } else {
    const ValueMode mode = w.mode == ValueMode::Default || w.mode == ValueMode::Absolute ? ValueMode::Direct : w.mode;
    double d = wrap_modulo(w.value, kTurn) - angle;  // each spindle's own angle (0 at the start)
    if (d < 0) d += kTurn;  // now the positive way in [0, 360)
    if (mode == ValueMode::AbsoluteNegative && d > 0) d = kTurn - d;
    if (mode == ValueMode::Direct && d > kTurn / 2) d = kTurn - d;
    m.travel = d;
  }
  const double reached = wrap_modulo(w.mode == ValueMode::Incremental ? angle + w.value : w.value, kTurn);
  if (master) {
    master_braking_ = {};
    spindle_angle_ = reached;
    state_.spindle = SpindleState::Stopped;  // in position control, stopped at the angle
    run_up_ = standing_run_up();              // a later M3/M4 ramps from standstill
  } else {
    other_spindles_[number].state = SpindleState::Stopped;
    other_spindles_[number].angle_deg = reached;
  }
  m.block_synchronous = w.kind == AxisWordKind::SPos;
  if (!m.block_synchronous) mark_running(m, angle, m.travel);
  ctx.positioning.push_back(std::move(m));
}

double Interpreter::move_extra_axis(const BlockContext& ctx, size_t i, double value, parser::ValueMode mode,
                                    uint32_t column) {
  const ExtraAxes::Travel t = extra_axes_.travel_to(i, value, mode, state_.absolute, geometry_unit());
  if (t.alarm != 0) raise(ctx, t.alarm, t.detail, column);
  const machine::AxisData& a = extra_axes_.data(i);
  const double end = extra_axes_.position(i) + t.travel;
  if (!a.modulo && (end < a.min_mm - 1e-9 || end > a.max_mm + 1e-9)) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "axis %s at %.3f, limits %.3f .. %.3f", a.name.c_str(), end, a.min_mm, a.max_mm);
    raise(ctx, 10720, buf, column);
  }
  extra_axes_.move(i, t.travel);
  return t.travel;
}

std::vector<ExtraAxisMove> Interpreter::take_extra_axis_moves(BlockContext& ctx) {
  std::vector<ExtraAxisMove> moves;
  for (const auto& [i, word] : ctx.extra_words) {
    const double start = extra_axes_.position(i);
    const double travel = move_extra_axis(ctx, i, word->value, word->mode, word->column);
    if (travel != 0)
      moves.push_back({static_cast<int>(i), extra_axes_.data(i).name, start, travel, extra_axes_.in_feed_group(i),
                       extra_axes_.feed_weight(i)});
  }
  return moves;
}

void Interpreter::attach_extra_axes(BlockContext& ctx, PathElement& e, std::vector<ExtraAxisMove> moves) {
  if (moves.empty()) return;
  // The smoothing stage rounds corners of X/Y/Z paths only (corner_smoothing.hpp): a corner of a
  // block that moves a further axis passes as under G64, which is said rather than silent.
  const int code = e.smoothing.code;
  if (!e.rapid && (code == 641 || code == 642 || code == 643 || code == 645) &&
      (e.dynamics.transition == TransitionMode::SmoothDistance || e.dynamics.transition == TransitionMode::SmoothTolerance))
    warn_once(ctx, "G" + std::to_string(code) + " corner rounding of blocks that move further axes (" + moves.front().name +
                       " ...): their corners are planned as under G64", 0);
  e.extra_axes = std::move(moves);
  // F refers to the feed group's length (G93: the block time fills the whole length).
  if (!e.rapid) e.feed_mm_s = feed_mm_s(ctx, e.path_length(), e.curve->end() - e.curve->start());
}

void Interpreter::mark_running(const PositioningMove& m, double from, double travel) {
  // A POSA/SPOSA starts with its block: the clock knows when it arrives (WAITP waits for that,
  // $AA_IM reads where it is meanwhile).
  const double start = nominal_time_s();
  const double duration = m.lead_time_s + move_to_rest_s(m.travel, m.entry_velocity, m.velocity, m.accel, m.jerk);
  extra_axes_.mark_running({m.axis, from, travel, start + m.lead_time_s, start + duration, m.velocity, m.accel});
}

void Interpreter::wait_for(BlockContext& ctx, const std::string& axis) {
  ctx.waits.push_back(axis);
  ctx.waits_until_s = std::max(ctx.waits_until_s, extra_axes_.clear_running(axis));
}

void Interpreter::emit_axis_waits(BlockContext& ctx) {
  if (ctx.waits.empty()) return;
  // The interpreter's clock waits with the block (the planner times the wait itself).
  if (ctx.waits_until_s > nominal_time_s()) {
    nominal_time_s_ += ctx.waits_until_s - nominal_time_s();
    ++work_additions_;
  }
  ctx.waits_until_s = 0;
  PathElement e = element_template(ctx, ElementKind::AxisWait);
  e.wait_axes = std::move(ctx.waits);
  e.label = "WAIT";
  for (const auto& a : e.wait_axes) e.label += " " + a;
  ctx.waits.clear();
  emit(std::move(e));
}

void Interpreter::emit_positioning(BlockContext& ctx) {
  if (ctx.positioning.empty()) return;
  PathElement e = element_template(ctx, ElementKind::Positioning);
  e.label = ctx.positioning.front().block_synchronous ? "POS" : "POSA";
  for (const auto& m : ctx.positioning) e.label += " " + m.axis;
  e.positioning = std::move(ctx.positioning);
  ctx.positioning.clear();
  emit(std::move(e));
}

}  // namespace drycut::interp
