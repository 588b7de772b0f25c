// The curves of motion blocks: lines, circles (all G2/G3/CIP/CT forms, built in the workpiece
// system and mapped through the frame) and spline runs.
#include <cmath>
#include <numbers>

#include "interp/geometry/line_curve.hpp"
#include "interp/interpreter.hpp"
#include "interp/interpreter_block.hpp"

namespace drycut::interp {

using Eigen::Vector3d;
using parser::AddressWord;
using parser::ValueMode;
using namespace detail;

PathElement Interpreter::build_line(BlockContext& ctx, const Vector3d& target) {
  PathElement e = element_template(ctx, ElementKind::Line);
  e.rapid = state_.motion == MotionMode::Rapid;
  e.label = e.rapid ? "G0" : std::string(motion_mode_name(state_.motion));
  e.curve = std::make_shared<geometry::LineCurve>(position_, target);
  if (!e.rapid) e.feed_mm_s = feed_mm_s(ctx, e.path_length(), target - position_);
  return e;
}

PathElement Interpreter::build_arc(BlockContext& ctx, const Target& target) {
  const double unit = state_.inch ? kMmPerInch : 1.0;
  // The circle is built where the program describes it. With a pure translation that is the
  // machine system shifted (exact, as before frames); otherwise the workpiece system, and the
  // finished circle goes through the frame (a mirror turns G2 into G3 by itself).
  const Frame& frame = block_frame(ctx);
  const bool in_machine = frame.is_pure_translation();
  // Absolute centres and CIP points are tip positions: in the machine system they get the length.
  const Vector3d shift = in_machine ? Vector3d(frame.offset() + target.length_after) : Vector3d::Zero();
  const Vector3d start = in_machine ? position_ : frame.to_inner(position_ - target.length_before);
  const Vector3d end = in_machine ? target.machine : target.workpiece;
  const geometry::Plane plane = to_geometry_plane(state_.plane);
  geometry::ArcTolerance tolerance{profile_.circle_error_const_mm, profile_.circle_error_factor};
  geometry::ArcResult result;
  PathElement e = element_template(ctx, ElementKind::Arc);
  e.label = std::string(motion_mode_name(state_.motion));

  if (state_.motion == MotionMode::ArcThroughPoint) {
    // CIP: intermediate point I1/J1/K1 follows G90/G91 (and AC/IC) like an end point.
    Vector3d mid = start;
    bool any = false;
    const char* names[3] = {"I1", "J1", "K1"};
    for (int i = 0; i < 3; ++i) {
      if (const AddressWord* a = ctx.block.find_address(names[i])) {
        any = true;
        const bool incremental = is_incremental(*a);
        const double value = a->value * unit * state_.diameter.value_factor(i, a->mode, incremental);
        mid[i] = incremental ? start[i] + value : value + shift[i];
      }
    }
    if (!any) raise(ctx, 14040, "CIP needs an intermediate point I1/J1/K1");
    result = geometry::arc_through_point(start, mid, end);
  } else if (state_.motion == MotionMode::ArcTangent) {
    if (!has_last_tangent_) raise(ctx, 14040, "CT needs a preceding motion to be tangent to");
    const Vector3d tangent = in_machine ? last_tangent_ : frame.vector_to_inner(last_tangent_).normalized();
    result = geometry::arc_tangent(start, tangent, end, plane);
  } else {
    const bool cw = state_.motion == MotionMode::ArcCw;
    const AddressWord* cr = ctx.block.find_address("CR");
    const AddressWord* ar = ctx.block.find_address("AR");
    const AddressWord* turn = ctx.block.find_address("TURN");
    int turns = 0;
    if (turn) {
      if (turn->value < 0 || turn->value > kMaxTurns || turn->value != std::floor(turn->value))
        raise(ctx, 14048, "TURN=" + std::to_string(turn->value), turn->column);
      turns = static_cast<int>(turn->value);
    }
    bool has_center = false;
    Vector3d center = start;
    const char* names[3] = {"I", "J", "K"};
    for (int i = 0; i < 3; ++i) {
      if (const AddressWord* a = ctx.block.find_address(names[i])) {
        has_center = true;
        // I/J/K are relative to the start point unless written I=AC(..). Under diameter
        // programming an absolute centre is a diameter, a relative one a radius (P1).
        center[i] = a->mode == ValueMode::Absolute
                        ? a->value * unit * state_.diameter.position_factor(i, false) + shift[i]
                        : start[i] + a->value * unit;
      }
    }
    if (!has_center && polar_words(ctx).any()) {
      // G2/G3 AP= RP=: a circle about the pole (in the plane; the normal coordinate is the start's).
      const PlaneIndices axes = state_.plane_indices();
      has_center = true;
      center[axes.first] = state_.polar.pole()[axes.first] + shift[axes.first];
      center[axes.second] = state_.polar.pole()[axes.second] + shift[axes.second];
    }
    if (cr) {
      if (cr->value == 0) raise(ctx, 14040, "CR=0", cr->column);
      if (!(std::abs(cr->value) <= kMaxAddressValue)) raise(ctx, 12160, "CR outside the control's value range", cr->column);
      result = geometry::arc_from_radius(start, end, cr->value * unit, cw, plane, {}, turns);
    } else if (ar && has_center) {
      result = geometry::arc_from_angle_and_center(start, end, center, ar->value * std::numbers::pi / 180.0, cw, plane,
                                                   turns);
    } else if (ar) {
      result = geometry::arc_from_angle_and_end(start, end, ar->value * std::numbers::pi / 180.0, cw, plane, turns);
    } else if (has_center) {
      result = geometry::arc_from_center(start, end, center, cw, plane, turns, tolerance);
    } else {
      raise(ctx, 14040, "G2/G3 needs a centre (I/J/K), a radius (CR=) or an angle (AR=)");
    }
  }
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
