#include "interp/cutter_compensation_corner.hpp"

#include <cmath>
#include <memory>
#include <numbers>

#include "interp/geometry/arc_curve.hpp"
#include "interp/geometry/line_curve.hpp"

namespace drycut::interp {

using geometry::Vec3;

OutsideCornerRule OutsideCornerRule::of(bool intersection_programmed, const machine::MachineProfile& profile) {
  constexpr double kRadPerDeg = std::numbers::pi / 180.0;
  return {intersection_programmed, profile.cutcom_corner_limit_deg * kRadPerDeg,
          profile.cutcom_curve_insert_limit_deg * kRadPerDeg};
}

bool OutsideCornerRule::intersects(double direction_change_rad) const {
  return intersection ? direction_change_rad <= corner_limit_rad : direction_change_rad < curve_insert_limit_rad;
}

Vec3 plane_direction(const Vec3& v, const CompensationPlane& plane) {
  const Vec3 w = v - plane.normal * plane.normal.dot(v);
  const double norm = w.norm();
  return norm > 1e-12 ? Vec3(w / norm) : Vec3(Vec3::Zero());
}

bool is_outside_corner(const Vec3& t_in, const Vec3& t_out, double offset_mm, const CompensationPlane& plane) {
  const double turn = plane.normal.dot(t_in.cross(t_out));  // > 0: left turn
  if (std::abs(turn) < 1e-12) return t_in.dot(t_out) < 0.0;
  return turn * offset_mm < 0.0;
}

std::vector<geometry::CurvePtr> outside_corner_curves(const Vec3& corner, const Vec3& t_in, const Vec3& t_out,
                                                      double offset_mm, const OutsideCornerRule& rule,
                                                      const CompensationPlane& plane) {
  const Vec3 from = corner + offset_mm * plane.normal.cross(t_in);
  const Vec3 to = corner + offset_mm * plane.normal.cross(t_out);
  const double radius = std::abs(offset_mm);
  const double angle = std::atan2(std::abs(plane.normal.dot(t_in.cross(t_out))), t_in.dot(t_out));
  if (rule.intersects(angle)) {
    // Both offset lines reach their intersection after r tan(angle/2) (symmetric about the corner).
    const Vec3 meet = from + radius * std::tan(0.5 * angle) * t_in;
    return {std::make_shared<geometry::LineCurve>(from, meet), std::make_shared<geometry::LineCurve>(meet, to)};
  }
  // The circle turns with the path: clockwise (negative) for a tool on the left, which is
  // outside only on right turns, counter-clockwise for a tool on the right.
  const Vec3 e1 = plane.normal.cross(t_in) * (offset_mm > 0.0 ? 1.0 : -1.0);
  const Vec3 e2 = plane.normal.cross(e1);
  const double sweep = offset_mm > 0.0 ? -angle : angle;
  return {std::make_shared<geometry::ArcCurve>(corner, radius, e1, e2, 0.0, sweep, 0.0)};
}

}  // namespace drycut::interp
