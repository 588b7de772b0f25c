#include "interp/geometry/arc_curve.hpp"

#include <algorithm>
#include <Eigen/Geometry>
#include <cmath>

namespace drycut::geometry {

ArcCurve::ArcCurve(Vec3 centre, double radius, Plane plane, double start_angle, double sweep,
                   double axial_travel)
    : ArcCurve(std::move(centre), radius, plane_axes(plane).first, plane_axes(plane).second,
               start_angle, sweep, axial_travel) {}

ArcCurve::ArcCurve(Vec3 centre, double radius, Vec3 e1, Vec3 e2, double start_angle, double sweep,
                   double axial_travel)
    : centre_(std::move(centre)),
      radius_(std::abs(radius)),
      e1_(std::move(e1)),
      e2_(std::move(e2)),
      normal_(e1_.cross(e2_)),
      start_angle_(start_angle),
      sweep_(sweep),
      axial_travel_(axial_travel) {
  // A zero sweep has no angular parameter: the element degenerates to a straight axial move.
  pitch_ = sweep_ != 0.0 ? axial_travel_ / sweep_ : 0.0;
  speed_ = std::hypot(radius_, pitch_);
  length_ = sweep_ != 0.0 ? std::abs(sweep_) * speed_ : std::abs(axial_travel_);
  curvature_ = (sweep_ != 0.0 && speed_ > 0.0) ? radius_ / (speed_ * speed_) : 0.0;
  start_point_ = evaluate(0.0);
  end_point_ = evaluate(length_);
}

CurvePoint ArcCurve::at(double s) const {
  // The ends are asked for far more often than any other point (joins, corners, positions):
  // kept from the constructor.
  if (s <= 0.0) return start_point_;
  if (s >= length_) return end_point_;
  return evaluate(s);
}

double ArcCurve::axis_radius(int i) const { return std::hypot(e1_[i], e2_[i]); }

double ArcCurve::axis_phase(int i) const { return std::atan2(e2_[i], e1_[i]); }

Vec3 ArcCurve::position_at_angle(double phi) const {
  return centre_ + radius_ * (std::cos(phi) * e1_ + std::sin(phi) * e2_) + pitch_ * (phi - start_angle_) * normal_;
}

CurvePoint ArcCurve::evaluate(double s) const {
  s = std::clamp(s, 0.0, length_);
  CurvePoint p;
  if (sweep_ == 0.0 || speed_ == 0.0) {
    const double dir = axial_travel_ < 0.0 ? -1.0 : 1.0;
    p.position = centre_ + radius_ * (std::cos(start_angle_) * e1_ + std::sin(start_angle_) * e2_) +
                 dir * s * normal_;
    p.tangent = dir * normal_;
    return p;
  }
  const double sign = sweep_ > 0.0 ? 1.0 : -1.0;
  const double dphi = sign * s / speed_;
  const double phi = start_angle_ + dphi;
  const double c = std::cos(phi), sn = std::sin(phi);
  const Vec3 radial = c * e1_ + sn * e2_;
  const Vec3 along = -sn * e1_ + c * e2_;
  p.position = centre_ + radius_ * radial + pitch_ * dphi * normal_;
  // Derivatives with respect to phi, scaled by dphi/ds = sign / speed.
  p.tangent = sign / speed_ * (radius_ * along + pitch_ * normal_);
  p.curvature_vector = -radius_ / (speed_ * speed_) * radial;
  p.curvature_rate = -sign * radius_ / (speed_ * speed_ * speed_) * along;
  p.curvature = curvature_;
  p.curvature_derivative = 0.0;
  return p;
}

}  // namespace drycut::geometry
