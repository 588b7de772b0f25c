#include "interp/contour_corners.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "interp/geometry/arc_curve.hpp"
#include "interp/geometry/line_curve.hpp"
#include "interp/geometry/trimmed_curve.hpp"
#include "interp/rounding_with_arcs.hpp"

namespace drycut::interp {

namespace {

constexpr int kNotModelled = 990002;
constexpr int kReduced = 990015;
constexpr double kAngleEps = 1e-9;   // radians: below it the blocks are parallel / reversing
constexpr double kLengthEps = 1e-9;  // mm
// More blocks than this without motion in the plane between the two: no corner (the manual).
constexpr int kMaxBlocksBetween = 3;

geometry::Vec3 plane_normal(const CompensationRequest& c) {
  if (c.tilted) return c.tilted_normal.normalized();
  geometry::Vec3 n = geometry::Vec3::Zero();
  n[c.plane_normal_axis] = 1.0;
  return n;
}

bool same_plane(const PathElement& a, const PathElement& b) {
  return a.compensation.plane_normal_axis == b.compensation.plane_normal_axis &&
         (plane_normal(a.compensation) - plane_normal(b.compensation)).norm() < 1e-9;
}

bool is_straight(const PathElement& e) {
  // G0/G1 only (a thread or POLY block is a Line element too; its label names it).
  return e.kind == ElementKind::Line && e.curve && e.extra_axes.empty() && (e.label == "G0" || e.label == "G1");
}

// A circle (G2/G3, CIP, CT) without helical travel or extra axes: RND may round next to it.
bool is_planar_arc(const PathElement& e) {
  if (e.kind != ElementKind::Arc || !e.curve || !e.extra_axes.empty()) return false;
  const auto* arc = dynamic_cast<const geometry::ArcCurve*>(e.curve.get());
  return arc && std::abs(arc->axial_travel()) < kLengthEps;
}

bool can_round(const PathElement& e) { return e.corner.kind == ContourCornerKind::Round && is_planar_arc(e); }

}  // namespace

const char* corner_word(const ContourCornerRequest& r) {
  switch (r.kind) {
    case ContourCornerKind::Round: return r.modal ? "RNDM" : "RND";
    case ContourCornerKind::Chamfer: return "CHF";
    case ContourCornerKind::ChamferLeg: return "CHR";
    case ContourCornerKind::None: break;
  }
  return "";
}

double corner_leg(ContourCornerKind kind, double size_mm, double theta) {
  switch (kind) {
    case ContourCornerKind::Round: return size_mm * std::tan(theta / 2);
    case ContourCornerKind::Chamfer: return size_mm / (2 * std::cos(theta / 2));
    case ContourCornerKind::ChamferLeg: return size_mm;
    case ContourCornerKind::None: break;
  }
  return 0.0;
}

double corner_size_for_leg(ContourCornerKind kind, double leg_mm, double theta) {
  switch (kind) {
    case ContourCornerKind::Round: return leg_mm / std::tan(theta / 2);
    case ContourCornerKind::Chamfer: return leg_mm * 2 * std::cos(theta / 2);
    case ContourCornerKind::ChamferLeg: return leg_mm;
    case ContourCornerKind::None: break;
  }
  return 0.0;
}

std::optional<CornerGeometry> corner_geometry(ContourCornerKind kind, double size_mm, const geometry::Vec3& corner,
                                              const geometry::Vec3& u1, const geometry::Vec3& u2) {
  const double theta = std::acos(std::clamp(u1.dot(u2), -1.0, 1.0));
  if (!(theta > kAngleEps && theta < std::numbers::pi - kAngleEps) || !(size_mm > 0)) return std::nullopt;
  CornerGeometry g;
  g.leg = corner_leg(kind, size_mm, theta);
  const geometry::Vec3 p1 = corner - g.leg * u1, p2 = corner + g.leg * u2;
  if (kind == ContourCornerKind::Round) {
    const geometry::Vec3 w = (u2 - u2.dot(u1) * u1).normalized();
    const geometry::Vec3 centre = p1 + size_mm * w;
    g.curve = std::make_shared<geometry::ArcCurve>(centre, size_mm, -w, u1, 0.0, theta, 0.0);
  } else {
    g.curve = std::make_shared<geometry::LineCurve>(p1, p2);
  }
  return g;
}

void ContourCorners::warn(const PathElement& at, const std::string& what) {
  // Once per text and line: RNDM over a loop must not print it a thousand times.
  if (!warned_.insert(what + '@' + at.source.file_name() + ':' + std::to_string(at.source.line)).second) return;
  diagnostics_.warn(kNotModelled, what, SourceLocation{at.source.file_name(), at.source.line, 0}, at.source.text);
}

void ContourCorners::hold(PathElement&& line) {
  pending_ = std::move(line);
  between_.clear();
  blocks_since_ = 0;
}

void ContourCorners::flush() {
  if (pending_) next_->consume(std::move(*pending_));
  pending_.reset();
  for (auto& e : between_) next_->consume(std::move(e));
  between_.clear();
}

void ContourCorners::give_up(const std::string& why, bool modal_silent) {
  // RNDM before a stop or the end: there is no corner to round, nothing is lost.
  if (!(modal_silent && pending_->corner.modal))
    warn(*pending_, std::string(corner_word(pending_->corner)) + " " + why + ": not modelled, the corner stays sharp");
  flush();
}

void ContourCorners::consume(PathElement&& element) {
  if (pending_ && !element.is_motion()) {
    if (element.kind == ElementKind::DynamicsChange) {
      between_.push_back(std::move(element));
      return;
    }
    give_up("with a dwell, stop, tool change or positioning before the next motion", true);
  }
  if (pending_ && !insert_corner(element)) flush();
  if (element.corner.kind == ContourCornerKind::None) {
    next_->consume(std::move(element));
    return;
  }
  if (!is_straight(element) && !can_round(element)) {
    warn(element, std::string(corner_word(element.corner)) + " at the end of a " + element.label +
                      " block (modelled between straight blocks, and RND next to circles: the corner stays sharp)");
    element.corner = {};
    next_->consume(std::move(element));
    return;
  }
  hold(std::move(element));
}

void ContourCorners::finish() {
  if (pending_) give_up("without a following traversing block", true);
  next_->finish();
}

bool ContourCorners::insert_corner(PathElement& b) {
  PathElement& a = *pending_;
  if (!is_straight(b) && b.kind == ElementKind::Line) {
    give_up("before a block moving extra axes");
    return true;
  }
  const bool arcs = a.corner.kind == ContourCornerKind::Round && (is_planar_arc(a) || is_planar_arc(b)) &&
                    (is_straight(a) || is_planar_arc(a)) && (is_straight(b) || is_planar_arc(b));
  if (!arcs && (!is_straight(b) || !is_straight(a))) {
    give_up("before a " + b.label + " block, modelled only between straight G0/G1 blocks (RND next to circles too)");
    return true;
  }
  if (b.corner.program_level != a.corner.program_level) {
    give_up("with the next motion in another program level");
    return true;
  }
  // The manual: no corner across a plane change or after more than three blocks between.
  if (!same_plane(a, b) || blocks_since_ - 1 > kMaxBlocksBetween) return false;
  const geometry::Vec3 n = plane_normal(a.compensation);
  if (arcs) return insert_rounding_with_arcs(b, n);
  const geometry::Vec3 start = a.curve->start(), corner = a.curve->end(), end = b.curve->end();
  const double la = a.curve->length(), lb = b.curve->length();
  if (la < kLengthEps || lb < kLengthEps) return false;
  const geometry::Vec3 u1 = (corner - start) / la, u2 = (end - corner) / lb;
  if (std::abs(u1.dot(n)) > 1e-9 || std::abs(u2.dot(n)) > 1e-9) {
    give_up("between blocks with a component along the plane normal");
    return true;
  }
  const double theta = std::acos(std::clamp(u1.dot(u2), -1.0, 1.0));
  if (theta >= std::numbers::pi - kAngleEps) {
    give_up("at a reversal of direction");
    return true;
  }
  double size = a.corner.size_mm;
  std::optional<CornerGeometry> g = corner_geometry(a.corner.kind, size, corner, u1, u2);
  if (!g) return false;  // parallel: no corner
  const double room = std::min(la, lb);
  if (g->leg > room + kLengthEps) {
    const double reduced = corner_size_for_leg(a.corner.kind, room, theta);
    char text[160];
    std::snprintf(text, sizeof text, "%s=%.4g reduced to %.4g mm: the blocks are too short", corner_word(a.corner),
                  size, reduced);
    diagnostics_.warn(kReduced, text, SourceLocation{a.source.file_name(), a.source.line, 0}, a.source.text);
    size = reduced;
    g = corner_geometry(a.corner.kind, size, corner, u1, u2);
    if (!g) return false;
  }
  const geometry::Vec3 p1 = g->curve->start(), p2 = g->curve->end();

  PathElement inserted = corner_element(a, b, a.corner.kind == ContourCornerKind::Round ? ElementKind::Arc : ElementKind::Line, g->curve);
  const bool first_left = (p1 - start).norm() > kLengthEps;
  if (first_left) a.curve = std::make_shared<geometry::LineCurve>(start, p1);
  hand_on_corner(first_left, std::move(inserted));
  b.curve = std::make_shared<geometry::LineCurve>(p2, end);
  return true;
}

PathElement ContourCorners::corner_element(PathElement& a, const PathElement& b, ElementKind kind,
                                           geometry::CurvePtr curve) {
  // The inserted element: the first block's source, dynamics and compensation; FRC/FRCM or the
  // second block's feed (rapid after a G0). The first block gives up its request and its G9.
  PathElement inserted = a;
  inserted.kind = kind;
  inserted.curve = std::move(curve);
  inserted.label = corner_word(a.corner);
  inserted.rapid = b.rapid;
  inserted.feed_mm_s = b.rapid ? 0.0 : a.corner.feed_mm_s > 0 ? a.corner.feed_mm_s : b.feed_mm_s;
  inserted.compressible = false;
  inserted.corner = {};
  a.dynamics.exact_stop_this_block = false;  // G9 acts at the end of the block, after the corner
  a.corner = {};
  return inserted;
}

void ContourCorners::hand_on_corner(bool first_left, PathElement&& inserted) {
  // The (cut) first block if anything is left of it, the corner element, what came between.
  if (first_left) next_->consume(std::move(*pending_));
  pending_.reset();
  next_->consume(std::move(inserted));
  for (auto& e : between_) next_->consume(std::move(e));
  between_.clear();
  ++inserted_;
}

bool ContourCorners::insert_rounding_with_arcs(PathElement& b, const geometry::Vec3& n) {
  PathElement& a = *pending_;
  for (const PathElement* e : {&a, &b}) {
    const auto* arc = dynamic_cast<const geometry::ArcCurve*>(e->curve.get());
    if (arc && std::abs(std::abs(arc->normal().dot(n)) - 1.0) > 1e-9) {
      give_up("next to a circle outside the working plane");
      return true;
    }
    if (!arc && std::abs((e->curve->end() - e->curve->start()).normalized().dot(n)) > 1e-9) {
      give_up("between blocks with a component along the plane normal");
      return true;
    }
  }
  if (a.curve->length() < kLengthEps || b.curve->length() < kLengthEps) return false;
  const std::optional<CurvedRounding> r = rounding_with_arcs(a.curve, b.curve, a.corner.size_mm, n);
  if (!r) {
    // Tangent sides have no corner (silently); a rounding that does not fit is said.
    const geometry::Vec3 t1 = a.curve->at(a.curve->length()).tangent, t2 = b.curve->at(0).tangent;
    if (t1.normalized().dot(t2.normalized()) > 1.0 - 1e-12) return false;
    give_up("does not fit between the blocks (no rounding of that radius touches both)");
    return true;
  }
  PathElement inserted = corner_element(a, b, ElementKind::Arc, r->curve);
  a.curve = geometry::trim_curve(a.curve, 0.0, r->end_of_first);
  hand_on_corner(true, std::move(inserted));
  b.curve = geometry::trim_curve(b.curve, r->start_of_second, b.curve->length());
  return true;
}

}  // namespace drycut::interp
