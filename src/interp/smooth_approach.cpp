#include "interp/smooth_approach.hpp"

#include <cmath>
#include <memory>
#include <numbers>

#include "interp/geometry/arc_curve.hpp"
#include "interp/geometry/line_curve.hpp"

namespace drycut::interp {

using geometry::Vec3;

namespace {

constexpr double kNoLength = 1e-9;  // mm: a piece shorter than this is left out

Vec3 in_plane(const Vec3& v, const Vec3& n) { return v - n * n.dot(v); }
Vec3 at_height(const Vec3& p, double height, const Vec3& n) { return in_plane(p, n) + n * height; }

// +1: from (to) the left of t, -1: the right. `other` is P0, the point the movement comes from
// (goes to).
int side_of(const SarRequest& r, int compensation_side, const Vec3& other, const Vec3& p4, const Vec3& left) {
  if (r.side_rule == 141) return 1;
  if (r.side_rule == 142) return -1;
  if (r.side_rule == 140 && compensation_side != 0) return compensation_side;
  return (other - p4).dot(left) >= 0.0 ? 1 : -1;  // left lies in the plane
}

// The contour circle's radius on the programmed contour: DISR is the tool centre's.
double contour_radius(const SarRequest& r, double radius, int compensation_side, int side) {
  if (compensation_side == 0) return r.disr_mm;
  return side == compensation_side ? r.disr_mm + radius : r.disr_mm - radius;
}

void add_line(std::vector<SarPiece>& out, const Vec3& a, const Vec3& b, SarSpeed speed, bool contour = false,
              bool keep_empty = false) {
  if (!keep_empty && (b - a).norm() < kNoLength) return;
  out.push_back({std::make_shared<geometry::LineCurve>(a, b), speed, contour});
}

// The arc around `centre` (in the plane of `start`) from `start`, turning `sweep` about n, rising
// `rise` along n.
void add_arc(std::vector<SarPiece>& out, const Vec3& centre, const Vec3& start, const Vec3& n, double sweep,
             double rise, SarSpeed speed) {
  const Vec3 from_centre = in_plane(start - centre, n);
  const double radius = from_centre.norm();
  if (radius < kNoLength) return;
  const Vec3 e1 = from_centre / radius;
  const Vec3 e2 = n.cross(e1);
  out.push_back({std::make_shared<geometry::ArcCurve>(at_height(centre, n.dot(start), n), radius, e1, e2, 0.0, sweep,
                                                      rise),
                 speed, true});
}

// The contour's direction t in the plane and its left normal n x t; false when t has no
// component in the plane.
bool plane_direction(const Vec3& tangent, const Vec3& n, Vec3& t, Vec3& left) {
  const Vec3 t_plane = in_plane(tangent, n);
  if (t_plane.norm() < 1e-9) return false;
  t = t_plane.normalized();
  left = n.cross(t);
  return true;
}

double sweep_of(SarShape shape, int side) {
  return side * (shape == SarShape::Semicircle ? std::numbers::pi : std::numbers::pi / 2);
}

}  // namespace

std::vector<SarPiece> approach_pieces(const Vec3& p0, const Vec3& p4, const Vec3& tangent, const Vec3& normal,
                                      const SarRequest& request, double radius, int compensation_side) {
  std::vector<SarPiece> out;
  const Vec3& n = normal;
  Vec3 t, left;
  if (!plane_direction(tangent, n, t, left)) return out;
  const int side = side_of(request, compensation_side, p0, p4, left);
  // P3 in the plane, and the circle's centre.
  Vec3 p3 = p4, centre = p4;
  if (request.shape == SarShape::Line) {
    p3 = p4 - (request.disr_mm + (compensation_side != 0 ? radius : 0.0)) * t;
  } else {
    const double r = contour_radius(request, radius, compensation_side, side);
    if (!(r > kNoLength)) return out;
    centre = p4 + side * r * left;
    p3 = request.shape == SarShape::Quadrant ? Vec3(centre - r * t) : Vec3(p4 + 2.0 * side * r * left);
  }
  const double h0 = n.dot(p0), h4 = n.dot(p4), hc = request.clearance_height;
  const Vec3 p1 = at_height(p3, h0, n);
  // Under compensation this move is the selection's approach: kept even without length (P0
  // above the contour's start), the compensation moves the tool to the offset from there.
  add_line(out, p0, p1, SarSpeed::Before, false, compensation_side != 0);
  const double contour_start = request.in_plane ? h4 : hc;
  add_line(out, p1, at_height(p3, hc, n), SarSpeed::Before);
  if (request.in_plane) add_line(out, at_height(p3, hc, n), at_height(p3, h4, n), SarSpeed::Fad);
  // G340: the contour descends from the clearance to P4 at FAD; G341: in the plane at F.
  const SarSpeed contour_speed = request.in_plane ? SarSpeed::Own : SarSpeed::Fad;
  const Vec3 start = at_height(p3, contour_start, n);
  if (request.shape == SarShape::Line) {
    add_line(out, start, p4, contour_speed, true);
  } else {
    add_arc(out, centre, start, n, sweep_of(request.shape, side), h4 - contour_start, contour_speed);
  }
  return out;
}

std::vector<SarPiece> retraction_pieces(const Vec3& p4, const Vec3& tangent, const Vec3* p0_in_plane,
                                        double p0_height, const Vec3& normal, const SarRequest& request,
                                        double radius, int compensation_side, bool on_tool_centre) {
  std::vector<SarPiece> out;
  const Vec3& n = normal;
  Vec3 t, left;
  if (!plane_direction(tangent, n, t, left)) return out;
  // Without an end point in the plane G143 has no side to read: it leaves to the left.
  const Vec3 p0_guess = p0_in_plane ? at_height(*p0_in_plane, p0_height, n) : Vec3(p4 + left);
  const int side = side_of(request, compensation_side, p0_guess, p4, left);
  const double h4 = n.dot(p4), hc = request.clearance_height;
  // On the tool centre (the block deselects the compensation): from the contour end's offset,
  // the circle of radius DISR, the line of DISR + r. On the programmed contour otherwise.
  const bool centre = on_tool_centre && compensation_side != 0;
  const Vec3 start = centre ? Vec3(p4 + compensation_side * radius * left) : p4;
  // G340: the contour rises from P4 to the clearance (at FAD); G341: it stays in P4's plane
  // (at the speed before the block), the rise to the clearance follows at FAD.
  const double contour_end = request.in_plane ? h4 : hc;
  const SarSpeed contour_speed = request.in_plane ? SarSpeed::Before : SarSpeed::Fad;
  if (request.shape == SarShape::Line) {
    const Vec3 p3 = start + (request.disr_mm + (compensation_side != 0 ? radius : 0.0)) * t;
    add_line(out, start, at_height(p3, contour_end, n), contour_speed, true);
  } else {
    const double r = centre ? request.disr_mm : contour_radius(request, radius, compensation_side, side);
    if (!(r > kNoLength)) return out;
    add_arc(out, start + side * r * left, start, n, sweep_of(request.shape, side), contour_end - h4, contour_speed);
  }
  if (out.empty()) return out;
  const Vec3 p3 = out.back().curve->end();
  const Vec3 p2 = at_height(p3, hc, n);
  if (request.in_plane) add_line(out, p3, p2, SarSpeed::Fad);
  const Vec3 p1 = at_height(p3, p0_height, n);
  add_line(out, p2, p1, SarSpeed::Own);
  add_line(out, p1, p0_in_plane ? at_height(*p0_in_plane, p0_height, n) : p1, SarSpeed::Own);
  return out;
}

}  // namespace drycut::interp
