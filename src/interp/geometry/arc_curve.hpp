#pragma once
// Circular arc or helix: a circle of `radius` around `centre` in the plane spanned by (e1, e2),
// swept by `sweep` radians (positive = counter-clockwise about e1 x e2) from `start_angle`,
// while moving `axial_travel` mm linearly along the normal e1 x e2.
//   P(phi) = centre + radius (cos phi e1 + sin phi e2) + axial_travel (phi - start_angle) / sweep * n
// Exact closed forms: length = sqrt((radius sweep)^2 + axial_travel^2), curvature = r / (r^2 + c^2)
// with c = axial_travel / sweep (mm per radian).
#include <algorithm>
#include <cmath>
#include <numbers>

#include "interp/geometry/curve.hpp"
#include "interp/geometry/plane.hpp"

namespace drycut::geometry {

class ArcCurve final : public Curve {
 public:
  // Arc in a working plane (G2/G3, CT).
  ArcCurve(Vec3 centre, double radius, Plane plane, double start_angle, double sweep, double axial_travel);
  // Arc in an arbitrary plane (CIP); e1 and e2 must be orthonormal.
  ArcCurve(Vec3 centre, double radius, Vec3 e1, Vec3 e2, double start_angle, double sweep, double axial_travel);

  double length() const override { return length_; }
  CurvePoint at(double s) const override;
  Vec3 start() const override { return start_point_.position; }
  Vec3 end() const override { return end_point_.position; }
  double max_curvature() const override { return curvature_; }

  const Vec3& centre() const { return centre_; }
  double radius() const { return radius_; }
  double start_angle() const { return start_angle_; }
  double sweep() const { return sweep_; }
  double axial_travel() const { return axial_travel_; }
  Vec3 normal() const { return normal_; }
  const Vec3& first_axis() const { return e1_; }   // e1: angle 0
  const Vec3& second_axis() const { return e2_; }  // e2: angle pi/2

  // Per axis i the circle's coordinate is radius·R_i·cos(phi − α_i) (plus the axial part):
  // R_i = |(e1_i, e2_i)| (0: the axis lies along the normal) and α_i = atan2(e2_i, e1_i). An
  // axis turns (its extremes, the software limits' points) at α_i + k·π, its curvature
  // component peaks there and its tangent component at α_i + π/2 + k·π.
  double axis_radius(int i) const;
  double axis_phase(int i) const;
  // Calls f(phi) for every angle beta + k·period (k integer) strictly inside the swept range,
  // in ascending order of phi.
  template <typename F>
  void for_each_angle_inside(double beta, double period, F&& f) const {
    const double lo = std::min(start_angle_, start_angle_ + sweep_), hi = std::max(start_angle_, start_angle_ + sweep_);
    for (double phi = beta + std::ceil((lo - beta) / period) * period; phi < hi; phi += period)
      if (phi > lo) f(phi);
  }
  // The point at angle phi (the helix's axial part in proportion to phi − start_angle).
  Vec3 position_at_angle(double phi) const;
  // Calls f(point) at every point strictly inside the sweep where an axis's coordinate turns
  // (α_i + k·π: its extremes, where the software limits are checked besides the ends).
  template <typename F>
  void for_each_axis_extreme(F&& f) const {
    for (int i = 0; i < 3; ++i) {
      if (axis_radius(i) < 1e-12) continue;  // along the normal
      for_each_angle_inside(axis_phase(i), std::numbers::pi, [&](double phi) { f(position_at_angle(phi)); });
    }
  }

 private:
  Vec3 centre_;
  double radius_;
  Vec3 e1_, e2_, normal_;
  double start_angle_;
  double sweep_;
  double axial_travel_;
  double pitch_;          // axial mm per radian of sweep
  double speed_;          // |dP/dphi| = sqrt(r^2 + pitch^2)
  double length_;
  double curvature_;
  CurvePoint start_point_, end_point_;  // evaluate(0), evaluate(length_)

  CurvePoint evaluate(double s) const;
};

}  // namespace drycut::geometry
