#include "interp/geometry/arc_solvers.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <sstream>

#include "interp/geometry/arc_curve.hpp"
#include "interp/geometry/line_curve.hpp"

namespace drycut::geometry {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
// Points closer than this (mm) are the same point; far below any programmable resolution.
constexpr double kSamePoint = 1e-9;

using Vec2 = Eigen::Vector2d;

struct PlaneCoords {
  PlaneAxes axes;
  Vec2 in_plane(const Vec3& p) const { return {p.dot(axes.first), p.dot(axes.second)}; }
  double axial(const Vec3& p) const { return p.dot(axes.normal); }
  Vec3 to_space(const Vec2& q, double axial) const {
    return q.x() * axes.first + q.y() * axes.second + axial * axes.normal;
  }
};

ArcResult failure(int alarm, std::string detail) {
  ArcResult r;
  r.alarm = alarm;
  r.detail = std::move(detail);
  return r;
}

std::string fmt(double v) {
  std::ostringstream o;
  o.precision(6);
  o << std::fixed << v;
  return o.str();
}

// Counter-clockwise angle from direction a to direction b in [0, 2 pi).
double ccw_angle(const Vec2& a, const Vec2& b) {
  double d = std::atan2(b.y(), b.x()) - std::atan2(a.y(), a.x());
  if (d < 0.0) d += kTwoPi;
  if (d >= kTwoPi) d -= kTwoPi;
  return d;
}

bool finite(const Vec3& v) { return v.allFinite(); }

// The arc from start around centre (plane coordinates) to end, in the programmed direction.
ArcResult build_plane_arc(const PlaneCoords& pc, const Vec2& a, const Vec2& b, const Vec2& centre,
                          double start_axial, double axial_travel, bool clockwise, int turns,
                          bool full_circle) {
  const Vec2 ra = a - centre;
  const Vec2 rb = b - centre;
  const double radius = ra.norm();
  double ccw = ccw_angle(ra, rb);
  double sweep;
  if (full_circle) {
    sweep = kTwoPi;
  } else if (clockwise) {
    sweep = ccw == 0.0 ? kTwoPi : kTwoPi - ccw;
  } else {
    sweep = ccw == 0.0 ? kTwoPi : ccw;
  }
  sweep += kTwoPi * turns;
  if (clockwise) sweep = -sweep;
  ArcResult r;
  r.curve = std::make_shared<ArcCurve>(pc.to_space(centre, start_axial), radius, pc.axes.first,
                                       pc.axes.second, std::atan2(ra.y(), ra.x()), sweep, axial_travel);
  return r;
}

Vec2 left_normal(const Vec2& v) { return {-v.y(), v.x()}; }

}  // namespace

ArcResult arc_from_center(Vec3 start, Vec3 end, Vec3 centre, bool clockwise, Plane plane, int turns,
                          const ArcTolerance& tolerance) {
  if (!finite(start) || !finite(end) || !finite(centre)) return failure(14040, "non-finite coordinate");
  if (turns < 0) return failure(14048, "TURN=" + std::to_string(turns) + " is negative");
  const PlaneCoords pc{plane_axes(plane)};
  const Vec2 a = pc.in_plane(start), b = pc.in_plane(end);
  Vec2 c = pc.in_plane(centre);
  const double r_start = (a - c).norm();
  const double r_end = (b - c).norm();
  if (r_start < kSamePoint) return failure(14040, "start point coincides with the centre (radius 0)");
  const double allowed = std::max(tolerance.error_const_mm, r_start * tolerance.error_factor);
  if (std::abs(r_start - r_end) > allowed) {
    return failure(14040, "start radius " + fmt(r_start) + " mm, end radius " + fmt(r_end) +
                              " mm, difference exceeds " + fmt(allowed) + " mm");
  }
  const Vec2 chord = b - a;
  const bool full_circle = chord.norm() < kSamePoint;
  if (!full_circle) {
    // Move the centre onto the perpendicular bisector (nearest point), so both radii agree.
    const Vec2 mid = 0.5 * (a + b);
    const Vec2 dir = chord.normalized();
    c -= dir * (c - mid).dot(dir);
    if ((a - c).norm() < kSamePoint) return failure(14040, "corrected centre lies on the start point");
  }
  return build_plane_arc(pc, a, b, c, pc.axial(start), pc.axial(end) - pc.axial(start), clockwise,
                         turns, full_circle);
}

ArcResult arc_from_radius(Vec3 start, Vec3 end, double cr_signed, bool clockwise, Plane plane,
                          const ArcTolerance& tolerance, int turns) {
  if (!finite(start) || !finite(end) || !std::isfinite(cr_signed)) return failure(14040, "non-finite value");
  if (cr_signed == 0.0) return failure(14040, "CR=0");
  const PlaneCoords pc{plane_axes(plane)};
  const Vec2 a = pc.in_plane(start), b = pc.in_plane(end);
  const Vec2 chord = b - a;
  const double d = chord.norm();
  if (d < kSamePoint) return failure(14040, "CR with start point == end point (full circle needs I/J/K)");
  const double r = std::abs(cr_signed);
  double half = 0.5 * d;
  if (half > r) {
    const double allowed = std::max(tolerance.error_const_mm, r * tolerance.error_factor);
    if (d - 2.0 * r > allowed) {
      return failure(14040, "chord " + fmt(d) + " mm longer than diameter " + fmt(2.0 * r) + " mm");
    }
    half = r;  // within tolerance: half circle
  }
  const double h = std::sqrt(std::max(0.0, r * r - half * half));
  // Minor CCW arcs have their centre left of the chord direction; CW or CR<0 flip the side.
  const double side = (clockwise ? -1.0 : 1.0) * (cr_signed > 0.0 ? 1.0 : -1.0);
  const Vec2 centre = 0.5 * (a + b) + side * h * left_normal(chord / d);
  return build_plane_arc(pc, a, b, centre, pc.axial(start), pc.axial(end) - pc.axial(start), clockwise,
                         turns, false);
}

ArcResult arc_from_angle_and_center(Vec3 start, Vec3 end, Vec3 centre, double ar_rad, bool clockwise, Plane plane,
                                    int turns) {
  if (!finite(start) || !finite(end) || !finite(centre) || !std::isfinite(ar_rad))
    return failure(14040, "non-finite value");
  if (!(ar_rad > 0.0 && ar_rad <= kTwoPi + 1e-12)) {
    return failure(12160, "AR=" + fmt(ar_rad * 180.0 / std::numbers::pi) + " deg outside (0, 360]");
  }
  const PlaneCoords pc{plane_axes(plane)};
  const Vec2 a = pc.in_plane(start), c = pc.in_plane(centre);
  const Vec2 ra = a - c;
  const double radius = ra.norm();
  if (radius < kSamePoint) return failure(14040, "start point coincides with the centre (radius 0)");
  const double sweep = ar_rad + kTwoPi * turns;
  ArcResult r;
  r.curve = std::make_shared<ArcCurve>(pc.to_space(c, pc.axial(start)), radius, pc.axes.first,
                                       pc.axes.second, std::atan2(ra.y(), ra.x()), clockwise ? -sweep : sweep,
                                       pc.axial(end) - pc.axial(start));
  return r;
}

ArcResult arc_from_angle_and_end(Vec3 start, Vec3 end, double ar_rad, bool clockwise, Plane plane, int turns) {
  if (!finite(start) || !finite(end) || !std::isfinite(ar_rad)) return failure(14040, "non-finite value");
  if (!(ar_rad > 0.0 && ar_rad < kTwoPi)) {
    return failure(12160, "AR=" + fmt(ar_rad * 180.0 / std::numbers::pi) + " deg outside (0, 360) with end point");
  }
  const PlaneCoords pc{plane_axes(plane)};
  const Vec2 a = pc.in_plane(start), b = pc.in_plane(end);
  const Vec2 chord = b - a;
  const double d = chord.norm();
  if (d < kSamePoint) return failure(14040, "AR with start point == end point");
  // Distance of the centre from the chord midpoint; negative beyond 180 deg (other side).
  const double h = 0.5 * d / std::tan(0.5 * ar_rad);
  const Vec2 centre = 0.5 * (a + b) + (clockwise ? -1.0 : 1.0) * h * left_normal(chord / d);
  const Vec2 ra = a - centre;
  const double sweep = ar_rad + kTwoPi * turns;
  ArcResult r;
  r.curve = std::make_shared<ArcCurve>(pc.to_space(centre, pc.axial(start)), ra.norm(), pc.axes.first,
                                       pc.axes.second, std::atan2(ra.y(), ra.x()), clockwise ? -sweep : sweep,
                                       pc.axial(end) - pc.axial(start));
  return r;
}

ArcResult arc_through_point(Vec3 start, Vec3 intermediate, Vec3 end) {
  if (!finite(start) || !finite(intermediate) || !finite(end)) return failure(14040, "non-finite coordinate");
  const Vec3 u = intermediate - start;
  const Vec3 v = end - start;
  if (u.norm() < kSamePoint || v.norm() < kSamePoint || (end - intermediate).norm() < kSamePoint) {
    return failure(14040, "CIP: two of start, intermediate and end point coincide");
  }
  const Vec3 w = u.cross(v);
  // Collinear when the triangle's height is negligible against its longest side.
  const double longest = std::max({u.norm(), v.norm(), (end - intermediate).norm()});
  if (w.norm() / longest < 1e-9 * longest) return failure(14040, "CIP: the three points are collinear");
  // Circumcentre of the triangle (start, intermediate, end).
  const Vec3 centre = start + (u.squaredNorm() * v.cross(w) + v.squaredNorm() * w.cross(u)) /
                                  (2.0 * w.squaredNorm());
  const double radius = (start - centre).norm();
  const Vec3 e1 = (start - centre) / radius;
  const Vec3 normal = w.normalized();  // start -> intermediate -> end runs counter-clockwise about w
  const Vec3 e2 = normal.cross(e1);
  const Vec3 re = end - centre;
  double sweep = std::atan2(re.dot(e2), re.dot(e1));
  if (sweep <= 0.0) sweep += kTwoPi;
  ArcResult r;
  r.curve = std::make_shared<ArcCurve>(centre, radius, e1, e2, 0.0, sweep, 0.0);
  return r;
}

ArcResult arc_tangent(Vec3 start, Vec3 start_tangent, Vec3 end, Plane plane, const ArcTolerance& tolerance) {
  if (!finite(start) || !finite(start_tangent) || !finite(end)) return failure(14040, "non-finite coordinate");
  const PlaneCoords pc{plane_axes(plane)};
  const Vec2 a = pc.in_plane(start), b = pc.in_plane(end);
  Vec2 t = pc.in_plane(start_tangent);
  if (t.norm() < 1e-12) return failure(14040, "CT: previous direction has no component in the plane");
  t.normalize();
  const Vec2 chord = b - a;
  const double d = chord.norm();
  if (d < kSamePoint) return failure(14040, "CT with start point == end point");
  const Vec2 left = left_normal(t);
  const double across = chord.dot(left);
  if (std::abs(across) < 1e-12 * d) {
    if (chord.dot(t) > 0.0) {
      ArcResult r;
      r.curve = std::make_shared<LineCurve>(start, end);
      return r;
    }
    return failure(14040, "CT: end point lies straight behind the start tangent");
  }
  // Centre on the start normal, equidistant from start and end: rho = |chord|^2 / (2 chord.left).
  const double rho = chord.squaredNorm() / (2.0 * across);
  const Vec2 centre = a + rho * left;
  return arc_from_center(start, end, pc.to_space(centre, pc.axial(start)), rho < 0.0, plane, 0, tolerance);
}

}  // namespace drycut::geometry
