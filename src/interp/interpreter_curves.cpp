// The curves of motion blocks: lines, circles (all G2/G3/CIP/CT forms, built in the workpiece
// system and mapped through the frame) and spline runs.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <typeinfo>

#include "interp/cutting_speed_pieces.hpp"
#include "interp/feed_rate.hpp"
#include "interp/geometry/arc_curve.hpp"
#include "interp/geometry/line_curve.hpp"
#include "interp/interpreter.hpp"
#include "interp/interpreter_block.hpp"

namespace drycut::interp {

using Eigen::Vector3d;
using parser::AddressWord;
using parser::ValueMode;
using namespace detail;

// A block with a geometry end point (or a full circle): a point of the spline run, or the
// line, circle or polynomial element to the target; a spline run ends where its type does.
void Interpreter::move_to_target(BlockContext& ctx, std::vector<ExtraAxisMove> extra) {
  const Target programmed = target_position(ctx);
  const Vector3d& target = programmed.machine;
  length_applied_ = programmed.length_after;
  check_limits(ctx, target);
  const bool run_ends = spline_.active() && !(state_.spline_mode() && state_.motion == spline_.mode());
  if (run_ends && (state_.spline_mode() || state_.motion == MotionMode::ArcTangent)) {
    // A new spline type, or CT (which is tangent to the run's end itself): ETAN takes the chord.
    Vector3d direction = target - position_;
    if (direction.norm() > 1e-12) direction.normalize();
    end_spline_run(direction.norm() > 0 ? &direction : nullptr);
  }
  if (state_.spline_mode()) {
    if (!extra.empty()) warn_once(ctx, "extra axes in spline blocks (they move without time)", 0);
    add_spline_point(ctx, target);
    return;
  }
  const bool arc = state_.motion == MotionMode::ArcCw || state_.motion == MotionMode::ArcCcw ||
                   state_.motion == MotionMode::ArcThroughPoint || state_.motion == MotionMode::ArcTangent;
  if (state_.thread_mode()) start_thread_block(ctx);
  PathElement e = arc ? build_arc(ctx, programmed)
                  : state_.motion == MotionMode::Polynomial ? build_polynomial(ctx, target)
                                                            : build_line(ctx, target);
  if (spline_.active()) {
    // The run ends here; ETAN takes the direction this block starts in.
    Vector3d direction = e.curve->length() > 0 ? e.curve->at(0).tangent : Vector3d::Zero();
    end_spline_run(direction.norm() > 0 ? &direction : nullptr);
  }
  if (!extra.empty()) attach_extra_axes(ctx, e, std::move(extra));  // (most blocks move no extra axis)
  mark_for_compressor(ctx, e);
  request_corner(ctx, e);
  attach_cutting_speed_law(ctx, e);
  position_ = e.curve->end();
  if (position_ != target) check_limits(ctx, position_);  // a line ends at the target, checked above
  if (arc) check_arc_limits(ctx, *e.curve);
  // (Extra axes would travel once per piece: such a thread stays one block at its mean feed.)
  if (ctx.lead_change_mm > 0 && !arc && e.curve->length() > 0 && !e.rapid && e.feed_mm_s > 0 && e.extra_axes.empty() &&
      (state_.motion == MotionMode::ThreadIncreasing || state_.motion == MotionMode::ThreadDecreasing)) {
    emit_lead_change_thread(ctx, std::move(e));
    return;
  }
  emit(std::move(e));
}

// G34/G35: the lead, and with it the feed at a constant spindle speed, changes every revolution
// (Fundamentals, "Linear progressive/degressive lead change (G34, G35)"). The block is emitted as
// pieces of equal length, one per revolution (2 to 16), each at its exact mean feed: the block's
// time stays the closed form's (feed_rate.hpp), and the feed a trace or a dip shows rises (falls)
// along the thread instead of standing at the block's mean.
void Interpreter::emit_lead_change_thread(BlockContext& ctx, PathElement&& e) {
  const Vector3d a = e.curve->start(), b = e.curve->end();
  const double length = e.curve->length();
  double travel = std::abs((b - a)[state_.thread_lead_axis]);
  if (travel < 1e-9) travel = length;
  const bool increasing = state_.motion == MotionMode::ThreadIncreasing;
  const double lead = state_.thread_lead_mm, change = ctx.lead_change_mm;
  const double total = lead_change_revolutions(travel, lead, change, increasing);
  if (!(total > 0)) {
    emit(std::move(e));
    return;
  }
  const int pieces = static_cast<int>(std::ceil(std::clamp(total, 2.0, 16.0)));  // clamped before the cast
  const double block_time = length / e.feed_mm_s;
  double before = 0.0;
  for (int k = 1; k <= pieces; ++k) {
    const double n = lead_change_revolutions(travel * k / pieces, lead, change, increasing);
    const Vector3d from = a + (b - a) * (k - 1) / pieces, to = k == pieces ? b : Vector3d(a + (b - a) * k / pieces);
    PathElement p = block_piece(e, line_curve(from, to), (length / pieces) / (block_time * (n - before) / total), k, pieces);
    if (k > 1) p.run_up_start = 0;
    before = n;
    emit(std::move(p));
  }
}

// A circle reaches beyond its end points where an axis's coordinate turns: at the angles
// α_i + k·π of each axis i inside the sweep (the circle's coordinate i is r·R_i·cos(φ − α_i),
// geometry/arc_curve.hpp). The control monitors the software limits along the path
// (alarm 10720), so those points are checked as the end points are: a G2 whose end lies inside
// the limits but whose half circle leaves them is refused, not passed.
void Interpreter::check_arc_limits(const BlockContext& ctx, const geometry::Curve& curve) {
  if (typeid(curve) != typeid(geometry::ArcCurve)) return;
  const auto& arc = static_cast<const geometry::ArcCurve&>(curve);
  if (arc.sweep() == 0.0 || arc.radius() <= 0.0) return;
  arc.for_each_axis_extreme([&](const Vector3d& p) { check_limits(ctx, p); });
}

void Interpreter::attach_cutting_speed_law(BlockContext& ctx, PathElement& e) {
  // G96 with G95 on a facing or taper cut: the feed f·n follows the diameter along the block (n
  // from 200 to 900 rev/min on a face). The block keeps the one feed that gives it its true time;
  // the law lets the last stage before the planner give the feed its course as well, on the
  // element as chamfers, roundings and the tool radius compensation have left it.
  const bool line_or_arc = state_.motion == MotionMode::Linear || state_.motion == MotionMode::ArcCw ||
                           state_.motion == MotionMode::ArcCcw || state_.motion == MotionMode::ArcThroughPoint ||
                           state_.motion == MotionMode::ArcTangent;
  if (e.rapid || !state_.constant_cutting_speed || state_.feed_mode != FeedMode::PerRevolution || !line_or_arc ||
      !e.extra_axes.empty() || recorder_.active())
    return;
  // x(p) = to_inner(p - length)[axis] is affine in p: its offset and its gradient.
  const Frame& frame = block_frame(ctx);
  const int axis = state_.cutting_speed_axis;
  auto law = std::make_shared<CuttingSpeedLaw>();
  law->speed_mm_min = cutting_speed_mm_min(state_.cutting_speed);
  law->min_rpm = spindle_min_rpm_;
  law->max_rpm = g96_speed_ceiling();
  law->offset = frame.to_inner(-length_applied_)[axis];
  for (int i = 0; i < 3; ++i)
    law->along[i] = frame.to_inner(Vector3d::Unit(i) - length_applied_)[axis] - law->offset;
  e.cutting_speed = std::move(law);
}

PathElement Interpreter::build_line(BlockContext& ctx, const Vector3d& target) {
  PathElement e = element_template(ctx, ElementKind::Line);
  e.rapid = state_.motion == MotionMode::Rapid;
  e.label.assign(e.rapid ? std::string_view("G0") : motion_mode_name(state_.motion));
  e.curve = line_curve(position_, target);
  if (!e.rapid) e.feed_mm_s = feed_mm_s(ctx, e.path_length(), target - position_);
  if (state_.motion == MotionMode::Tapping || state_.motion == MotionMode::TappingRetract) limit_tapping_acceleration(e);
  return e;
}

// The system build_arc builds a circle in, and the circle's ends there.
struct Interpreter::ArcSpace {
  const Frame& frame;
  bool in_machine;  // the machine system shifted (the frame is a pure translation)
  Vector3d shift;   // added to absolute centres and CIP points
  Vector3d start, end;
  geometry::Plane plane;
  double unit;  // mm per programmed length unit
};

PathElement Interpreter::build_arc(BlockContext& ctx, const Target& target) {
  const double unit = state_.inch ? kMmPerInch : 1.0;
  // The circle is built where the program describes it. With a pure translation that is the
  // machine system shifted (exact, as before frames); otherwise the workpiece system, and the
  // finished circle goes through the frame (a mirror turns G2 into G3 by itself).
  const Frame& frame = block_frame(ctx);
  const bool in_machine = frame.is_pure_translation();
  const ArcSpace space{
      .frame = frame,
      .in_machine = in_machine,
      // Absolute centres and CIP points are tip positions: in the machine system they get the length.
      .shift = in_machine ? Vector3d(frame.offset() + target.length_after) : Vector3d::Zero(),
      .start = in_machine ? position_ : frame.to_inner(position_ - target.length_before),
      .end = in_machine ? target.machine : target.workpiece,
      .plane = to_geometry_plane(state_.plane),
      .unit = unit};
  PathElement e = element_template(ctx, ElementKind::Arc);
  e.label = std::string(motion_mode_name(state_.motion));

  geometry::ArcResult result;
  if (state_.motion == MotionMode::ArcThroughPoint)
    result = cip_arc(ctx, space);
  else if (state_.motion == MotionMode::ArcTangent)
    result = ct_arc(ctx, space);
  else
    result = g2_g3_arc(ctx, space);
  if (result.alarm != 0) raise(ctx, result.alarm, result.detail);
  if (!(std::isfinite(result.curve->length()) && result.curve->end().allFinite()))
    raise(ctx, 14040, "the circle cannot be computed (radius or angle out of range)");
  if (in_machine) {
    e.curve = result.curve;
  } else {
    // Mapped through the frame, then lifted by the tool length to the carrier.
    auto mapped = transform_curve(result.curve, Frame::translation(target.length_after).then(frame));
    if (!mapped) raise(ctx, kUnsupported, "circle under unequal scale factors in its plane (SCALE/ASCALE)");
    e.curve = *mapped;
  }
  e.feed_mm_s = feed_mm_s(ctx, e.path_length(), target.machine - position_);
  return e;
}

geometry::ArcResult Interpreter::cip_arc(const BlockContext& ctx, const ArcSpace& space) const {
  // CIP: intermediate point I1/J1/K1 follows G90/G91 (and AC/IC) like an end point.
  Vector3d mid = space.start;
  bool any = false;
  const char* names[3] = {"I1", "J1", "K1"};
  for (int i = 0; i < 3; ++i) {
    if (const AddressWord* a = ctx.block.find_address(names[i])) {
      any = true;
      const bool incremental = is_incremental(*a);
      const double value = a->value * space.unit * state_.diameter.value_factor(i, a->mode, incremental);
      mid[i] = incremental ? space.start[i] + value : value + space.shift[i];
    }
  }
  if (!any) raise(ctx, 14040, "CIP needs an intermediate point I1/J1/K1");
  return geometry::arc_through_point(space.start, mid, space.end);
}

geometry::ArcResult Interpreter::ct_arc(const BlockContext& ctx, const ArcSpace& space) const {
  if (!has_last_tangent_) raise(ctx, 14040, "CT needs a preceding motion to be tangent to");
  const Vector3d tangent =
      space.in_machine ? last_tangent_ : space.frame.vector_to_inner(last_tangent_).normalized();
  return geometry::arc_tangent(space.start, tangent, space.end, space.plane);
}

// G2/G3 by centre, radius (CR=) or angle (AR=), with TURN= extra revolutions.
geometry::ArcResult Interpreter::g2_g3_arc(const BlockContext& ctx, const ArcSpace& space) const {
  const bool cw = state_.motion == MotionMode::ArcCw;
  const AddressWord* cr = ctx.block.find_address("CR");
  const AddressWord* ar = ctx.block.find_address("AR");
  const int turns = arc_turns(ctx);
  Vector3d center = space.start;
  const bool has_center = arc_centre(ctx, space, center);
  const Vector3d& start = space.start;
  const Vector3d& end = space.end;
  const geometry::Plane plane = space.plane;
  if (cr) {
    if (cr->value == 0) raise(ctx, 14040, "CR=0", cr->column);
    if (!(std::abs(cr->value) <= kMaxAddressValue))
      raise(ctx, 12160, "CR outside the control's value range", cr->column);
    return geometry::arc_from_radius(start, end, cr->value * space.unit, cw, plane, {}, turns);
  }
  const double ar_rad = ar ? ar->value * std::numbers::pi / 180.0 : 0.0;
  if (ar && has_center)
    return geometry::arc_from_angle_and_center(start, end, center, ar_rad, cw, plane, turns);
  if (ar) return geometry::arc_from_angle_and_end(start, end, ar_rad, cw, plane, turns);
  if (has_center) {
    const geometry::ArcTolerance tolerance{profile_.circle_error_const_mm, profile_.circle_error_factor};
    return geometry::arc_from_center(start, end, center, cw, plane, turns, tolerance);
  }
  raise(ctx, 14040, "G2/G3 needs a centre (I/J/K), a radius (CR=) or an angle (AR=)");
}

// TURN=: the full revolutions a G2/G3 circle makes besides its arc (0 without TURN).
int Interpreter::arc_turns(const BlockContext& ctx) const {
  const AddressWord* turn = ctx.block.find_address("TURN");
  if (!turn) return 0;
  if (turn->value < 0 || turn->value > kMaxTurns || turn->value != std::floor(turn->value))
    raise(ctx, 14048, "TURN=" + std::to_string(turn->value), turn->column);
  return static_cast<int>(turn->value);
}

// The centre of a G2/G3 circle from I/J/K or, without them, the pole of AP=/RP= into `center`;
// false when the block gives neither.
bool Interpreter::arc_centre(const BlockContext& ctx, const ArcSpace& space, Vector3d& center) const {
  bool has_center = false;
  const char* names[3] = {"I", "J", "K"};
  for (int i = 0; i < 3; ++i) {
    if (const AddressWord* a = ctx.block.find_address(names[i])) {
      has_center = true;
      // I/J/K are relative to the start point unless written I=AC(..). Under diameter
      // programming an absolute centre is a diameter, a relative one a radius (P1).
      center[i] = a->mode == ValueMode::Absolute
                      ? a->value * space.unit * state_.diameter.position_factor(i, false) + space.shift[i]
                      : space.start[i] + a->value * space.unit;
    }
  }
  if (!has_center && polar_words(ctx).any()) {
    // G2/G3 AP= RP=: a circle about the pole (in the plane; the normal coordinate is the start's).
    const PlaneIndices axes = state_.plane_indices();
    has_center = true;
    center[axes.first] = state_.polar.pole()[axes.first] + space.shift[axes.first];
    center[axes.second] = state_.polar.pole()[axes.second] + space.shift[axes.second];
  }
  return has_center;
}

void Interpreter::add_spline_point(BlockContext& ctx, const Vector3d& target) {
  if (!spline_.active()) {
    Vector3d tangent = has_last_tangent_ ? last_tangent_ : Vector3d::Zero();
    SplineCondition begin = state_.spline_begin;
    // BTAN with nothing before it has no direction to take: the start is natural then.
    if (begin == SplineCondition::Tangent && !has_last_tangent_) begin = SplineCondition::Natural;
    spline_.begin(state_.motion, position_, to_spline_end(begin, tangent), state_.bspline_degree,
                  profile_.cubic_spline_global ? 0 : profile_.cubic_spline_blocks);
    quota_.start(spline_quota(state_.motion, profile_.cubic_spline_blocks));
  }
  PathElement e = element_template(ctx, ElementKind::SplineSpan);
  // The span's length is known only when the run is solved: G93 takes the chord here.
  if (state_.feed_mode == FeedMode::InverseTime) warn_once(ctx, "G93 with splines: the block time uses the chord", 0);
  e.feed_mm_s = feed_mm_s(ctx, (target - position_).norm(), target - position_);
  e.label = std::string(motion_mode_name(state_.motion));
  double weight = 1.0, knot_span = 0.0;
  if (const AddressWord* pw = ctx.block.find_address("PW")) {
    if (pw->value < 0 || pw->value > 3) raise(ctx, 12160, "PW must be 0..3", pw->column);
    weight = pw->value;
  }
  if (const AddressWord* pl = ctx.block.find_address("PL")) {
    if (!(pl->value > 0 && pl->value <= kMaxAddressValue))
      raise(ctx, 12160, "PL must be > 0 and within the control's value range", pl->column);
    knot_span = pl->value * (state_.inch ? kMmPerInch : 1.0);
  }
  // Field by field: the text reuses the buffer of the previous block's (a BlockRef built and
  // moved in cost a malloc/free per spline block).
  if (last_spline_block_.file != ctx.block.file) last_spline_block_.file = ctx.block.file;
  last_spline_block_.line = ctx.block.line;
  last_spline_block_.text.assign(ctx.block.text);
  try {
    spline_.add(target, weight, knot_span, std::move(e));
    spline_.drain(sink_);
  } catch (const AlarmError& error) {
    // The geometry knows what is wrong but not where: give the alarm this block's location.
    if (!error.alarm().where.file.empty()) throw;
    Alarm located = error.alarm();
    located.where = {ctx.file_name(), ctx.block.line, 0};
    located.block = ctx.block.text;
    throw AlarmError(std::move(located));
  }
  position_ = target;
  if (spline_.has_last_tangent()) {
    last_tangent_ = spline_.last_tangent();
    has_last_tangent_ = true;
  }
}

void Interpreter::end_spline_run(const Vector3d* next_direction) {
  SplineCondition end = state_.spline_end;
  if (end == SplineCondition::Tangent && !next_direction) end = SplineCondition::Natural;
  try {
    spline_.finish(to_spline_end(end, next_direction ? *next_direction : Vector3d::Zero()));
    spline_.drain(sink_);
  } catch (const AlarmError& error) {
    // The run's last spans fail only now: the alarm belongs to the run's last block.
    if (!error.alarm().where.file.empty()) throw;
    Alarm located = error.alarm();
    located.where = {last_spline_block_.file_name(), last_spline_block_.line, 0};
    located.block = last_spline_block_.text;
    throw AlarmError(std::move(located));
  }
  if (spline_.has_last_tangent()) {
    last_tangent_ = spline_.last_tangent();
    has_last_tangent_ = true;
  }
  spline_.reset();
  quota_.stop();
}

}  // namespace drycut::interp
