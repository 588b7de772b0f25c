// Smooth approach and retraction (SAR, G147 ... G348): the interpreter's part. The geometry is
// smooth_approach.hpp's; here the block's words, the speeds and the order of the elements.
// Speeds (PGsl Fundamentals, "Smooth approach and retraction", approach and retraction
// velocities): on approach the movements up to the clearance (P0 -> P2) run at the speed in force
// before the SAR block (rapid under G0), the infeed below the clearance (G341) or the descending
// contour (G340) at FAD, the rest at the block's F (FAD missing: at F). On retraction the roles
// swap: the contour at the speed before the block, FAD where the approach had it, and the moves
// from the clearance to the end point at the block's own speed (rapid when the block's motion is
// G0).
#include <cmath>

#include "interp/geometry/arc_curve.hpp"
#include "interp/geometry/line_curve.hpp"
#include "interp/interpreter_block.hpp"

namespace drycut::interp {

using namespace detail;

namespace {

// The plane normal of the element's compensation plane, in the elements' coordinates.
Vector3d plane_normal(const CompensationRequest& c) {
  if (c.tilted) return c.tilted_normal.normalized();
  Vector3d n = Vector3d::Zero();
  n[c.plane_normal_axis] = 1.0;
  return n;
}

int side_sign(CompensationSide side) {
  return side == CompensationSide::Left ? 1 : side == CompensationSide::Right ? -1 : 0;
}

}  // namespace

bool Interpreter::apply_smooth_approach_address(BlockContext& ctx, const parser::AddressWord& a) {
  const std::string_view n = a.name;
  if (n == "DISR") {
    state_.sar_disr = a.value * geometry_unit();
  } else if (n == "DISCL") {
    state_.sar_discl = a.value * geometry_unit();
    state_.sar_discl_absolute = a.mode == parser::ValueMode::Absolute;
  } else if (n == "FAD") {
    if (a.value < 0) raise(ctx, 14800, "FAD=" + std::to_string(a.value), a.column);
    state_.sar_fad = a.value;
    state_.sar_fad_type = a.mode == parser::ValueMode::PerMinute ? 94 : a.mode == parser::ValueMode::PerRevolution ? 95 : 0;
  } else if (n == "DISRP") {
    warn_once(ctx, "DISRP= (the retraction plane of SAR: P1 is taken at the start/end point's height)", a.column);
  } else {
    return false;
  }
  return true;
}

void Interpreter::execute_smooth_approach(BlockContext& ctx, MotionMode modal_motion) {
  const bool approach = ctx.smooth_approach % 10 == 7;
  const Target programmed = target_position(ctx);
  const Vector3d target = programmed.machine;
  length_applied_ = programmed.length_after;
  check_limits(ctx, target);
  if (spline_.active()) end_spline_run(nullptr);
  const Vector3d start = position_;
  PathElement e = build_line(ctx, target);  // the block's own feed (state_.motion is G1 here)
  e.label = "G" + std::to_string(ctx.smooth_approach);
  const Vector3d normal = plane_normal(e.compensation);

  SarRequest request;
  request.shape = static_cast<SarShape>(ctx.smooth_approach / 100);
  request.in_plane = state_.sar_in_plane;
  request.side_rule = state_.sar_side_rule;
  request.disr_mm = state_.sar_disr;
  // The clearance is measured from the plane of the contour point: P4 on approach, the contour
  // end (where the tool is) on retraction.
  const Vector3d contour_point = approach ? target : start;
  request.clearance_height = normal.dot(contour_point) + state_.sar_discl;
  if (state_.sar_discl_absolute) {
    // DISCL=AC(v): the position v of the axis along the normal, in the workpiece system.
    Vector3d w = programmed.workpiece;
    w[e.compensation.plane_normal_axis] = state_.sar_discl;
    request.clearance_height = normal.dot(block_frame(ctx).to_outer(w) + programmed.length_after);
  }

  // Speeds: the feed before the block (its F and feed type), FAD and the block's own.
  SarSpeeds speeds;
  const auto feed_at = [&](double f, int type = 0) {
    const double own = state_.feed;
    const FeedMode own_mode = state_.feed_mode;
    state_.feed = f;
    if (type != 0) state_.feed_mode = type == 94 ? FeedMode::PerMinute : FeedMode::PerRevolution;
    const double v = feed_mm_s(ctx, (target - start).norm(), target - start);
    state_.feed = own;
    state_.feed_mode = own_mode;
    return v;
  };
  speeds.g0 = modal_motion == MotionMode::Rapid;
  speeds.before_mm_s = ctx.feed_before > 0 ? feed_at(ctx.feed_before) : e.feed_mm_s;
  speeds.fad_mm_s = state_.sar_fad > 0 ? feed_at(state_.sar_fad, state_.sar_fad_type) : 0.0;
  speeds.own_mm_s = e.feed_mm_s;
  position_ = target;

  const double radius = e.compensation.radius_mm;
  if (approach) {
    // The SAR block selects the compensation itself: the next block is not a selection block.
    compensation_selection_pending_ = false;
    const int side = side_sign(e.compensation.side);
    const bool checked = limits_checked(ctx);
    sar_pending_ =
        PendingApproach{std::move(e), request, normal, radius, side, speeds, !block_names_plane_axis_, checked};
    return;
  }
  // Retraction: from the contour's end along its last direction. With G40 in the block the
  // movements run on the tool centre, the compensation off; kept on, on the contour, compensated.
  CompensationSide before = ctx.compensation_before;
  if (before != CompensationSide::None && frame_mirrors_plane(block_frame(ctx)))
    before = before == CompensationSide::Left ? CompensationSide::Right : CompensationSide::Left;
  const CompensationSide after = e.compensation.side;
  const bool deselects = before != CompensationSide::None && after == CompensationSide::None;
  const Vector3d p0_plane = target;
  const auto pieces =
      has_last_tangent_
          ? retraction_pieces(start, last_tangent_, block_names_plane_axis_ ? &p0_plane : nullptr, normal.dot(target),
                              normal, request, radius, side_sign(deselects ? before : after), deselects)
          : std::vector<SarPiece>{};
  if (pieces.empty()) {
    warn_once(ctx, "smooth retraction without a contour direction in the plane (a straight move)", 0);
    emit(std::move(e));
    return;
  }
  position_ = pieces.back().curve->end();
  emit_smooth_approach_pieces(e, pieces, speeds, limits_checked(ctx));
}

bool Interpreter::hold_for_smooth_approach(PathElement& element) {
  if (!element.is_motion() || !element.curve || element.curve->length() <= 0) {
    sar_held_.push_back(std::move(element));  // emitted after the approach, in order
    return true;
  }
  if (sar_pending_->end_from_next) {
    // Its end point is P4; the SAR contour replaces its move, the next block gives the tangent.
    PathElement& sar = sar_pending_->element;
    sar.curve = std::make_shared<geometry::LineCurve>(sar.curve->start(), element.curve->end());
    sar_pending_->end_from_next = false;
    return true;
  }
  const Vector3d t = element.curve->at(0).tangent;
  release_smooth_approach(&t);
  return false;
}

void Interpreter::release_smooth_approach(const Vector3d* next_tangent) {
  PendingApproach pending = std::move(*sar_pending_);
  sar_pending_.reset();
  sar_releasing_ = true;
  const Vector3d p0 = pending.element.curve->start(), p4 = pending.element.curve->end();
  const auto pieces = next_tangent ? approach_pieces(p0, p4, *next_tangent, pending.normal, pending.request,
                                                     pending.radius, pending.compensation_side)
                                   : std::vector<SarPiece>{};
  if (pieces.empty()) {
    if (next_tangent) {  // (a program that ends first needs no word)
      const BlockRef& b = pending.element.source;
      diagnostics_.warn(kNotModelled,
                        "smooth approach: no approach contour (no direction in the plane, or a circle of DISR not "
                        "larger than the tool radius from the side away from the tool): a straight move",
                        {b.file_name(), b.line, 0}, b.text);
    }
    emit(std::move(pending.element));  // no contour to join: the straight move
  } else {
    emit_smooth_approach_pieces(pending.element, pieces, pending.speeds, pending.check_limits);
  }
  std::vector<PathElement> held = std::move(sar_held_);
  sar_held_.clear();
  sar_releasing_ = false;
  for (auto& h : held) emit(std::move(h));
}

void Interpreter::check_smooth_approach_limits(const PathElement& block_element, const geometry::Curve& curve) const {
  const auto check = [&](const Vector3d& p) {
    if (const auto violation = limit_violation(p)) {
      const BlockRef& b = block_element.source;
      throw AlarmError(make_alarm(10720, *violation + " (smooth approach/retraction)", {b.file_name(), b.line, 0}, b.text));
    }
  };
  check(curve.end());
  if (const auto* arc = dynamic_cast<const geometry::ArcCurve*>(&curve); arc && arc->sweep() != 0.0)
    arc->for_each_axis_extreme(check);
}

void Interpreter::emit_smooth_approach_pieces(const PathElement& block_element, const std::vector<SarPiece>& pieces,
                                              const SarSpeeds& speeds, bool check_limits) {
  // Approach: the contour is the block's end (its F); retraction: the contour comes first. Every
  // piece keeps the block's compensation (on a retraction with G40: off, the pieces run on the
  // tool centre).
  const bool approach = pieces.back().contour;
  for (size_t i = 0; i < pieces.size(); ++i) {
    if (check_limits) check_smooth_approach_limits(block_element, *pieces[i].curve);
    PathElement p = block_element;
    p.curve = pieces[i].curve;
    p.kind = dynamic_cast<const geometry::ArcCurve*>(p.curve.get()) ? ElementKind::Arc : ElementKind::Line;
    // Not `inserted`: each sub-movement ends where the SAR geometry puts it (in step with the
    // program for the compensation's normal axis), not a joint the compensation made.
    if (i > 0) p.run_up_start = 0;
    // DISR sizes the tool-centre path: F (FAD) is the tool centre's feed on it, not a contour
    // feed CFC would scale (drycut's reading [I]; the same on approach and retraction).
    p.compensation.contour_feed = ContourFeed::ToolCentre;
    bool rapid = false;
    double feed = speeds.own_mm_s;
    switch (pieces[i].speed) {
      case SarSpeed::Before:
        rapid = approach && speeds.g0;
        feed = speeds.before_mm_s;
        break;
      case SarSpeed::Fad:
        feed = speeds.fad_mm_s > 0 ? speeds.fad_mm_s : approach ? speeds.own_mm_s : speeds.before_mm_s;
        break;
      case SarSpeed::Own:
        rapid = !approach && speeds.g0;
        break;
    }
    p.rapid = rapid;
    p.feed_mm_s = rapid ? 0.0 : feed;
    emit(std::move(p));
  }
}

}  // namespace drycut::interp
