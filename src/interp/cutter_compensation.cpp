#include "interp/cutter_compensation.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "interp/cutter_compensation_corner.hpp"
#include "interp/cutter_compensation_crossing.hpp"
#include "interp/cutter_compensation_normal_axis.hpp"
#include "interp/geometry/arc_curve.hpp"
#include "interp/geometry/line_curve.hpp"

namespace drycut::interp {

using geometry::CurvePtr;
using geometry::Vec3;

namespace {

// Offset points of a joint closer than this are one point (tangential joint): no corner element.
constexpr double kJoinTolerance = 1e-6;  // mm
// A motion whose in-plane path is shorter than this has no direction in the plane.
constexpr double kZeroInPlaneLength = 1e-6;  // mm
// Output curves shorter than this are dropped (a piece trimmed to its joint).
constexpr double kNegligibleLength = 1e-9;  // mm
// Samples for the in-plane length of curved elements.
constexpr int kLengthSamples = 32;
// Bound on the cut/split passes for one new element (each removes a loop or a stretch).
constexpr int kMaxCrossingPasses = 1000;
// A shift along the plane normal below this is rounding: the curve is built unshifted.
constexpr double kNoShift = 1e-9;  // mm
// Under CDOF a fold's loop is searched beyond MD20240 (see the header), but not without end: a
// fold still open this many blocks after its own block is a collision (alarm 10751). A bound of
// drycut's memory and time, not machine behaviour: the thesis programs' folds close within 27.
constexpr int kFoldSearchBlocks = 256;

[[noreturn]] void raise(int number, const std::string& detail, const BlockRef& block) {
  throw AlarmError(make_alarm(number, detail, SourceLocation{block.file_name(), block.line, 0}, block.text));
}

double signed_offset(const CompensationRequest& request) {
  switch (request.side) {
    case CompensationSide::Left: return request.radius_mm;
    case CompensationSide::Right: return -request.radius_mm;
    case CompensationSide::None: break;
  }
  return 0.0;
}

// The plane the request compensates in: G17/G18/G19, or the plane a frame tilted (its first axis
// and normal in machine coordinates; the second axis completes a right-handed triple).
CompensationPlane compensation_plane(const CompensationRequest& request) {
  if (!request.tilted) return CompensationPlane::from_normal_axis(request.plane_normal_axis);
  return {request.tilted_normal, request.tilted_first, request.tilted_normal.cross(request.tilted_first)};
}

bool same_plane(const CompensationPlane& a, const CompensationPlane& b) {
  constexpr double kSameDirection = 1e-9;
  return (a.normal - b.normal).norm() < kSameDirection && (a.first - b.first).norm() < kSameDirection;
}

double in_plane_length(const geometry::Curve& curve, const CompensationPlane& plane) {
  if (curve.max_curvature() == 0.0) return plane.project(curve.end() - curve.start()).norm();
  double sum = 0.0;
  Eigen::Vector2d previous = plane.project(curve.start());
  for (int i = 1; i <= kLengthSamples; ++i) {
    const Eigen::Vector2d p = plane.project(curve.at(curve.length() * i / kLengthSamples).position);
    sum += (p - previous).norm();
    previous = p;
  }
  return sum;
}

bool counts_as_dummy(const PathElement& element) {
  switch (element.kind) {
    case ElementKind::Dwell:
    case ElementKind::Stop:
    case ElementKind::ToolChange:
    case ElementKind::DynamicsChange: return true;
    default: return element.is_motion();  // only motions without in-plane length get here
  }
}

ElementKind kind_of(const CurvePtr& curve, ElementKind fallback) {
  if (dynamic_cast<const geometry::LineCurve*>(curve.get()) != nullptr) return ElementKind::Line;
  if (dynamic_cast<const geometry::ArcCurve*>(curve.get()) != nullptr) return ElementKind::Arc;
  return fallback;
}

// The start direction of an element in the plane (its first in-plane tangent).
Vec3 start_direction(const geometry::Curve& curve, const CompensationPlane& plane) {
  Vec3 t = plane_direction(curve.at(0.0).tangent, plane);
  if (t.isZero()) t = plane_direction(curve.end() - curve.start(), plane);
  return t;
}

Vec3 end_direction(const geometry::Curve& curve, const CompensationPlane& plane) {
  Vec3 t = plane_direction(curve.at(curve.length()).tangent, plane);
  if (t.isZero()) t = plane_direction(curve.end() - curve.start(), plane);
  return t;
}

}  // namespace

CutterCompensation::CutterCompensation(ElementSink& downstream, const machine::MachineProfile& profile,
                                       Diagnostics& diagnostics)
    : downstream_(downstream), profile_(profile), diagnostics_(diagnostics) {}

void CutterCompensation::consume(PathElement&& element) {
  edge_reference_.apply(element);  // a turning tool's tip P, not its edge centre S, is guided
  if (phase_ == Phase::Inactive) {
    if (element.is_motion() && element.compensation.side != CompensationSide::None) {
      select(std::move(element));
      return;
    }
    if (element.is_motion() && element.curve) tool_position_ = element.curve->end();
    downstream_.consume(std::move(element));
    return;
  }
  if (element.is_motion() && element.compensation.side == CompensationSide::None) {
    deselect(std::move(element));
    return;
  }
  if (element.is_motion() && (element.compensation.plane_normal_axis != plane_axis_ ||
                              !same_plane(compensation_plane(element.compensation), plane_)))
    raise(10757, "plane changed while G41/G42 is active", element.source);
  if (!element.is_motion() || !element.curve || in_plane_length(*element.curve, plane_) < kZeroInPlaneLength) {
    count_dummy(element);
    window_.push_back(Item{std::move(element), std::nullopt, block_serial_, true});
    return;
  }
  dummy_count_ = 0;
  if (phase_ == Phase::Approaching) complete_approach(element);
  add_motion(element);
  release_old_blocks(check_blocks());
}

void CutterCompensation::finish() {
  if (phase_ == Phase::Approaching) {
    // Selected but never followed by a motion in the plane: the approach stays as programmed.
    emit(approach_, approach_.curve, true);
    flush_window();
  } else if (phase_ == Phase::Active) {
    flush_window();
  }
  phase_ = Phase::Inactive;
  downstream_.finish();
}

void CutterCompensation::count_dummy(const PathElement& element) {
  if (!counts_as_dummy(element)) return;
  if (++dummy_count_ > profile_.cutcom_maxnum_dummy_blocks)
    raise(10762,
          "more than " + std::to_string(profile_.cutcom_maxnum_dummy_blocks) +
              " blocks without motion in the compensation plane (MD20250)",
          element.source);
}

void CutterCompensation::select(PathElement approach) {
  plane_axis_ = approach.compensation.plane_normal_axis;
  plane_ = compensation_plane(approach.compensation);
  // A negative compensation value (radius + wear + OFFN below 0: CAM "wear" compensation with
  // radius 0 and a negative wear) is valid: the equidistant lies on the other side, as the
  // signed offset gives it (docs/controller-state.md "Negative compensation value").
  tool_position_ = approach.curve->start();  // the approach starts wherever the tool is
  approach_ = std::move(approach);
  phase_ = Phase::Approaching;
  dummy_count_ = 0;
}

void CutterCompensation::complete_approach(const PathElement& first) {
  const double d = signed_offset(first.compensation);
  const Vec3 from = approach_.curve->start(), corner = approach_.curve->end();
  const Vec3 t_first = start_direction(*first.curve, plane_);
  const Vec3 target = corner + d * plane_.normal.cross(t_first);
  const Vec3 t_approach = plane_direction(corner - from, plane_);
  const bool around = approach_.compensation.contour_approach && !t_approach.isZero() &&
                      is_outside_corner(t_approach, t_first, d, plane_);
  std::vector<CurvePtr> curves;
  if (around) {
    // KONT from behind the contour: perpendicular to the approach, then around the start point.
    const Vec3 beside = corner + d * plane_.normal.cross(t_approach);
    curves.push_back(std::make_shared<geometry::LineCurve>(from, beside));
    for (const auto& c : outside_corner_curves(corner, t_approach, t_first, d,
                                               corner_rule(approach_.compensation), plane_))
      curves.push_back(c);
  } else {
    curves.push_back(std::make_shared<geometry::LineCurve>(from, target));
  }
  // The approach stays in the window (in front of the elements programmed between it and the
  // first contour element): an entry that turns back sharply loops across it.
  ++block_serial_;
  for (size_t i = curves.size(); i-- > 0;) {
    PathElement part = approach_;
    part.kind = kind_of(curves[i], ElementKind::Line);
    window_.push_front(Item{std::move(part), OffsetPiece(curves[i], 0.0, plane_), block_serial_, false});
  }
  phase_ = Phase::Active;
}

void CutterCompensation::deselect(PathElement retract) {
  if (phase_ == Phase::Approaching) {
    // G40 right after the selection cancels it: both moves run as programmed.
    emit(approach_, approach_.curve, true);
    flush_window();
    phase_ = Phase::Inactive;
    consume(std::move(retract));
    return;
  }
  phase_ = Phase::Inactive;
  dummy_count_ = 0;
  if (!retract.curve || retract.kind != ElementKind::Line) {
    flush_window();
    // A connecting line is inserted in front of a retract that is not a straight move.
    if (retract.curve) emit(retract, retract.curve, true);
    return;
  }
  // The end of the compensated path: the last piece still in the window, else the last released.
  Vec3 from = tool_position_, direction = last_direction_;
  double offset = last_offset_;
  for (size_t i = window_.size(); i-- > 0;) {
    if (!window_[i].piece) continue;
    from = window_[i].piece->end();
    for (size_t k = i + 1; k-- > 0;)
      if (window_[k].piece && window_[k].piece->offset() != 0.0) {
        direction = end_direction(window_[k].piece->base(), plane_);
        offset = window_[k].piece->offset();
        break;
      }
    break;
  }
  const Vec3 corner = retract.curve->start(), goal = retract.curve->end();
  const Vec3 t_retract = plane_direction(goal - corner, plane_);
  std::vector<CurvePtr> curves;
  if (retract.compensation.contour_approach && !t_retract.isZero() && offset != 0.0 &&
      is_outside_corner(direction, t_retract, offset, plane_)) {
    // KONT: around the end point until perpendicular to the retract direction.
    curves = outside_corner_curves(corner, direction, t_retract, offset, corner_rule(retract.compensation),
                                   plane_);
    from = curves.back()->end();
  }
  curves.push_back(std::make_shared<geometry::LineCurve>(from, goal));
  // The retract takes part in the crossing search: a last span that bends back loops across it.
  ++block_serial_;
  const size_t first_new = window_.size();
  for (const auto& curve : curves) {
    PathElement part = retract;
    part.kind = kind_of(curve, ElementKind::Line);
    window_.push_back(Item{std::move(part), OffsetPiece(curve, 0.0, plane_), block_serial_, false});
  }
  resolve_crossings(first_new, check_blocks());
  flush_window();
}

OutsideCornerRule CutterCompensation::corner_rule(const CompensationRequest& c) const {
  return OutsideCornerRule::of(c.intersection_corners, profile_);
}

int CutterCompensation::check_blocks() const { return std::max(1, profile_.cutcom_maxnum_check_blocks); }

std::optional<size_t> CutterCompensation::last_piece_index() const {
  for (size_t i = window_.size(); i-- > 0;)
    if (window_[i].piece) return i;
  return std::nullopt;
}

void CutterCompensation::add_motion(const PathElement& element) {
  ++block_serial_;
  const double d = signed_offset(element.compensation);
  OffsetPiece piece(element.curve, d, plane_);
  const size_t first_new = window_.size();
  if (const auto previous = last_piece_index()) {
    const OffsetPiece& before = *window_[*previous].piece;
    const Vec3 from = before.end(), to = piece.start();
    auto push_corner = [&](const CurvePtr& curve, bool gap_bridge, bool extension = false) {
      PathElement corner = element;
      corner.kind = kind_of(curve, ElementKind::Line);
      corner.inserted = true;
      corner.offset_extension = extension;
      window_.push_back(Item{std::move(corner), OffsetPiece(curve, 0.0, plane_), block_serial_, gap_bridge});
    };
    if (plane_.project(to - from).norm() >= kJoinTolerance) {
      const Vec3 t_in = end_direction(before.base(), plane_), t_out = start_direction(*element.curve, plane_);
      if (before.offset() != d) {
        push_corner(std::make_shared<geometry::LineCurve>(from, to), false);  // radius or side changed
      } else if (is_outside_corner(t_in, t_out, d, plane_)) {
        const auto curves =
            outside_corner_curves(element.curve->start(), t_in, t_out, d, corner_rule(element.compensation), plane_);
        const bool intersection = curves.size() == 2;  // two straight pieces: the offsets meet (else a circle)
        for (const auto& curve : curves) push_corner(curve, false, intersection);
      } else {
        // Inside corner: the bridge closes the raw path; the crossing search cuts it out again.
        push_corner(std::make_shared<geometry::LineCurve>(from, to), true);
      }
    }
  }
  window_.push_back(Item{element, std::move(piece), block_serial_, false});
  resolve_crossings(first_new, check_blocks());
}

void CutterCompensation::resolve_crossings(size_t first_new, int check_blocks) {
  const int oldest_block = oldest_searched_block(check_blocks);
  size_t index = first_new;
  for (int pass = 0; pass < kMaxCrossingPasses && index < window_.size(); ++pass) {
    // A gap bridge is never cut at a crossing of its own: it only ever lies inside a cut stretch.
    if (!window_[index].piece || window_[index].gap_bridge) {
      ++index;
      continue;
    }
    // Crossings with earlier pieces, nearest first: a fold is closed by the crossing next to it
    // (a closed contour's offset also meets its own start, which is sound and stays). Of one
    // pair, the crossing first along the earlier piece closes the largest loop.
    std::optional<size_t> previous_piece;
    for (size_t k = index; k-- > 0;)
      if (window_[k].piece) {
        previous_piece = k;
        break;
      }
    bool cut = false;
    for (size_t k = index; k-- > 0 && !cut;) {
      if (!window_[k].piece || window_[k].gap_bridge || window_[k].block < oldest_block) continue;
      for (const PieceCrossing& crossing :
           find_crossings(*window_[k].piece, *window_[index].piece, previous_piece == k, plane_)) {
        if (!cut_out_is_defective(k, index, crossing)) continue;
        const size_t removed_before = static_cast<size_t>(
            std::count_if(window_.begin() + static_cast<long>(k) + 1, window_.begin() + static_cast<long>(index),
                          [](const Item& it) { return it.piece.has_value(); }));
        cut_between(k, index, crossing.u_earlier, crossing.u_later);
        index -= removed_before;
        cut = true;
        break;
      }
    }
    if (cut) continue;  // search again from the new start of the piece
    const auto loop = find_self_crossing(*window_[index].piece, plane_);
    if (loop && window_[index].piece->runs_backwards(loop->u_earlier, loop->u_later)) {
      Item second = window_[index];
      window_[index].piece->trim(window_[index].piece->u_begin(), loop->u_earlier);
      second.piece->trim(loop->u_later, second.piece->u_end());
      window_.insert(window_.begin() + static_cast<long>(index) + 1, std::move(second));
      ++index;
      continue;
    }
    ++index;
  }
}

bool CutterCompensation::cut_out_is_defective(size_t earlier, size_t later, const PieceCrossing& crossing) const {
  // Only a stretch the tool cannot follow is cut out: a gap bridge over an inside joint or an
  // offset running backwards. Elsewhere crossing offsets are the programmed contour's own
  // (closed contours, loops at another depth), and the control does not cut them.
  const OffsetPiece& first = *window_[earlier].piece;
  const OffsetPiece& last = *window_[later].piece;
  bool defect = first.runs_backwards(crossing.u_earlier, first.u_end()) ||
                last.runs_backwards(last.u_begin(), crossing.u_later);
  for (size_t i = earlier + 1; i < later && !defect; ++i)
    defect = window_[i].piece && (window_[i].gap_bridge || window_[i].piece->runs_backwards());
  // A loop that holds such a stretch is still the contour's own when it turns the way the
  // programmed contour turns between the same points (a pocket closed in the corner it started
  // from, its corner rounded with the tool's radius: the whole pocket is that loop).
  return defect && !loop_turns_as_programmed(earlier, later, crossing);
}

namespace {
// Twice the signed area of the closed polygon through `points` (shoelace): > 0 anticlockwise.
double twice_signed_area(const std::vector<Eigen::Vector2d>& points) {
  double sum = 0.0;
  for (size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector2d& a = points[i];
    const Eigen::Vector2d& b = points[(i + 1) % points.size()];
    sum += a.x() * b.y() - a.y() * b.x();
  }
  return sum;
}
}  // namespace

bool CutterCompensation::loop_turns_as_programmed(size_t earlier, size_t later, const PieceCrossing& crossing) const {
  // The loop of the tool-centre path from the crossing round to itself, and the programmed
  // contour between the same base points closed by the chord back. A loop an offset makes where
  // it folds over (a bend or corner tighter than the tool radius) runs against the programmed
  // contour's sense there; a loop of the contour itself runs with it. Corners inserted by the
  // compensation are no programmed contour: the base loop goes straight across them. A loop
  // through the approach or the retraction (no offset, not inserted) has no programmed
  // counterpart to compare with: it is left to the rule of cut_out_is_defective alone.
  std::vector<Eigen::Vector2d> offset_loop, base_loop;
  for (size_t i = earlier; i <= later; ++i) {
    if (!window_[i].piece) continue;
    const OffsetPiece& piece = *window_[i].piece;
    if (piece.offset() == 0.0 && !window_[i].element.inserted) return false;
    const double u0 = i == earlier ? crossing.u_earlier : piece.u_begin();
    const double u1 = i == later ? crossing.u_later : piece.u_end();
    const bool programmed = piece.offset() != 0.0;
    auto put = [&](double u) {
      offset_loop.push_back(plane_.project(piece.position(u)));
      if (programmed) base_loop.push_back(plane_.project(piece.base().at(u).position));
    };
    put(u0);
    for (const double u : piece.sample_parameters())
      if (u > u0 && u < u1) put(u);
    put(u1);
  }
  // Below this (mm², doubled) a loop has no sense of turning worth trusting: it stays a defect.
  constexpr double kLeastArea = 1e-9;
  const double offset_area = twice_signed_area(offset_loop), base_area = twice_signed_area(base_loop);
  if (std::abs(offset_area) < kLeastArea || std::abs(base_area) < kLeastArea) return false;
  return (offset_area > 0.0) == (base_area > 0.0);
}

void CutterCompensation::cut_between(size_t earlier, size_t later, double u_earlier, double u_later) {
  OffsetPiece& first = *window_[earlier].piece;
  first.trim(first.u_begin(), u_earlier);
  OffsetPiece& second = *window_[later].piece;
  second.trim(u_later, second.u_end());
  const int keep_a = window_[earlier].block, keep_b = window_[later].block;
  // Copied before the loop below moves the kept items out of the window.
  const BlockRef from = window_[earlier].element.source;
  const BlockRef to = window_[later].element.source;
  std::vector<int> warned;
  std::deque<Item> kept;
  for (size_t i = 0; i < window_.size(); ++i) {
    Item& item = window_[i];
    const bool between = i > earlier && i < later;
    if (between && item.piece) {
      // Passengers stay (they run at the crossing point); motion pieces are cut out. A piece
      // whose offset is a point (an inside rounding or arc of the tool's radius: RND=5 with a
      // 5 mm cutter) loses no path, so no block is skipped and nothing is warned.
      if (item.block != keep_a && item.block != keep_b && item.piece->in_plane_length() >= kZeroInPlaneLength &&
          std::find(warned.begin(), warned.end(), item.block) == warned.end()) {
        warned.push_back(item.block);
        // The catalogue text already says "skipped"; the detail says where the path was cut.
        diagnostics_.warn(10763,
                          "the tool-centre path crosses itself between " + from.file_name() + ":" +
                              std::to_string(from.line) + " and " + to.file_name() + ":" + std::to_string(to.line),
                          SourceLocation{item.element.source.file_name(), item.element.source.line, 0},
                          item.element.source.text);
      }
      continue;
    }
    kept.push_back(std::move(item));
  }
  window_ = std::move(kept);
}

std::optional<int> CutterCompensation::pending_fold_block() const {
  // The oldest fold still open under CDOF: an offset running backwards (not a gap bridge, which
  // is an inside corner and keeps the MD20240 reach).
  for (const Item& item : window_) {
    if (!item.piece || item.gap_bridge || item.piece->offset() == 0.0) continue;
    if (item.element.compensation.collision_detection) continue;
    if (item.piece->runs_backwards()) return item.block;
  }
  return std::nullopt;
}

int CutterCompensation::oldest_searched_block(int check_blocks) const {
  // MD20240 blocks back; while a fold has outlived that reach, back to the blocks it could reach
  // when it came in (the loop's incoming side), which the window keeps for it.
  const int reach = block_serial_ - check_blocks;
  const auto fold = pending_fold_block();
  if (fold && *fold <= reach) return std::min(reach, *fold - check_blocks);
  return reach;
}

void CutterCompensation::release_old_blocks(int check_blocks) {
  // The next block searches the blocks from block_serial_ + 1 - check_blocks on. An open fold
  // (CDOF) keeps itself and the blocks its loop may close with, up to kFoldSearchBlocks.
  const auto fold = pending_fold_block();
  const bool hold = fold && block_serial_ - *fold < kFoldSearchBlocks;
  while (!window_.empty() && window_.front().block <= block_serial_ - check_blocks) {
    if (hold && window_.front().block >= *fold - check_blocks) break;
    emit_front();
  }
  if (!hold) return;
  // An inside corner keeps its MD20240 reach while a fold holds the window.
  for (const Item& item : window_)
    if (item.piece && item.gap_bridge && item.block <= block_serial_ - check_blocks)
      raise(10751, "no intersection of the offset paths within the checked blocks (MD20240)", item.element.source);
}

void CutterCompensation::flush_window() {
  while (!window_.empty()) emit_front();
}

void CutterCompensation::emit_front() {
  Item item = std::move(window_.front());
  window_.pop_front();
  if (!item.piece) {
    emit_passenger(std::move(item.element));
    return;
  }
  if (item.gap_bridge)
    raise(10751, "no intersection of the offset paths within the checked blocks (MD20240)", item.element.source);
  if (item.piece->runs_backwards())
    raise(10751, "radius of curvature smaller than the tool radius on the compensation side", item.element.source);
  bool last_of_block = true;
  for (const Item& later : window_)
    if (later.piece && later.block == item.block) last_of_block = false;
  if (item.piece->offset() != 0.0) {
    last_direction_ = end_direction(item.piece->base(), plane_);
    last_offset_ = item.piece->offset();
  }
  const geometry::NormalRamp shift = normal_axis_shift(item);
  const bool shifted = shift.at_begin != 0.0 || shift.at_end != 0.0;
  CurvePtr curve = item.piece->build_curve(shift);
  // CFC compares the lengths as programmed: the shift along the normal is not a contour change.
  const double centre_mm = shifted ? item.piece->build_curve()->length() : curve->length();
  apply_constant_contour_feed(item.element, item.piece->u_end() - item.piece->u_begin(), centre_mm);
  emit(std::move(item.element), std::move(curve), last_of_block);
}

geometry::NormalRamp CutterCompensation::normal_axis_shift(const Item& item) const {
  // The spans from this piece up to the next point in step with the program (see
  // cutter_compensation_normal_axis.hpp); passengers take part with their own normal travel.
  std::vector<NormalAxisSpan> ahead;
  auto add_piece = [&](const Item& it) {
    const OffsetPiece& piece = *it.piece;
    ahead.push_back(NormalAxisSpan{piece.in_plane_length(), piece.normal_start(), piece.normal_end(),
                                   it.element.inserted || it.gap_bridge, piece.reaches_base_end(), it.block});
    return ahead.back().in_step_at_end && !ahead.back().inserted;
  };
  bool anchored = add_piece(item);
  for (size_t i = 0; i < window_.size() && !anchored; ++i) {
    const Item& it = window_[i];
    if (it.piece) {
      anchored = add_piece(it);
    } else if (it.element.is_motion() && it.element.curve) {
      const double travel = plane_.normal.dot(it.element.curve->end() - it.element.curve->start());
      ahead.push_back(NormalAxisSpan{0.0, 0.0, travel, false, false, it.block});
    }
  }
  const double tool = plane_.normal.dot(tool_position_);
  const double end = normal_value_at_end(tool, ahead);
  geometry::NormalRamp shift{tool - item.piece->normal_start(), end - item.piece->normal_end()};
  if (std::abs(shift.at_begin) < kNoShift) shift.at_begin = 0.0;
  if (std::abs(shift.at_end) < kNoShift) shift.at_end = 0.0;
  return shift;
}

void CutterCompensation::apply_constant_contour_feed(PathElement& element, double contour_mm, double centre_mm) const {
  // CFC (the reset default): F holds on the programmed contour. Over a stretch whose tool-centre
  // path is longer (outside) or shorter (inside) than the contour, the tool centre moves faster
  // or slower by that ratio; SD42528 CUTCOM_DECEL_LIMIT bounds the slow-down on inside curves.
  // CFIN slows down inside only; CFTCP: F is the tool centre's feed, nothing is scaled.
  const ContourFeed mode = element.compensation.contour_feed;
  if (mode == ContourFeed::ToolCentre) return;
  if (contour_mm <= kNegligibleLength || centre_mm <= kNegligibleLength) return;
  double ratio = centre_mm / contour_mm;
  if (mode == ContourFeed::InsideOnly) ratio = std::min(ratio, 1.0);
  const double scale = std::max(ratio, profile_.cutcom_decel_limit);
  element.feed_scale = scale;
  element.feed_mm_s *= scale;
}

void CutterCompensation::emit_passenger(PathElement element) {
  if (element.is_motion() && element.curve) {
    // No in-plane motion: only the normal-axis travel, at the current tool-centre point.
    const Vec3 travel = element.curve->end() - element.curve->start();
    emit(std::move(element), std::make_shared<geometry::LineCurve>(tool_position_, tool_position_ + travel), true);
    return;
  }
  downstream_.consume(std::move(element));
}

void CutterCompensation::emit(PathElement element, CurvePtr curve, bool last_of_block) {
  auto not_final = [](PathElement& e) {
    e.dynamics.exact_stop_this_block = false;
    if (e.dynamics.transition == TransitionMode::ExactStop) e.dynamics.transition = TransitionMode::Continuous;
  };
  if ((curve->start() - tool_position_).norm() > kJoinTolerance) {
    // Cut-out stretches and normal-axis moves can leave a step: join it by a straight move.
    PathElement connector = element;
    connector.kind = ElementKind::Line;
    connector.inserted = true;
    connector.extra_axes.clear();  // the block's extra axes move once, with its last piece
    connector.curve = std::make_shared<geometry::LineCurve>(tool_position_, curve->start());
    not_final(connector);
    downstream_.consume(std::move(connector));
    tool_position_ = curve->start();
  }
  if (curve->length() < kNegligibleLength && !last_of_block) return;
  if (!last_of_block) element.extra_axes.clear();  // extra axes move with the block's last piece
  element.kind = kind_of(curve, element.kind);
  element.curve = curve;
  if (!last_of_block) not_final(element);
  tool_position_ = curve->end();
  downstream_.consume(std::move(element));
}

}  // namespace drycut::interp
