#pragma once
// A path curve evaluated by arc length: F is a path velocity, so nothing downstream of the
// interpreter ever sees a spline parameter. Units: millimetres.
#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products in every curve
#include <memory>

namespace drycut::geometry {

using Vec3 = Eigen::Vector3d;

// The curve's local differential geometry at arc length s.
struct CurvePoint {
  Vec3 position = Vec3::Zero();
  Vec3 tangent = Vec3::UnitX();          // unit tangent dP/ds
  Vec3 curvature_vector = Vec3::Zero();  // d²P/ds² = kappa * principal normal
  Vec3 curvature_rate = Vec3::Zero();    // d³P/ds³ (for jerk limits)
  double curvature = 0.0;                // |d²P/ds²| in 1/mm
  double curvature_derivative = 0.0;     // d(kappa)/ds in 1/mm²
};

class Curve {
 public:
  virtual ~Curve() = default;
  // Arc length in mm; relative error below 1e-6 for every curve type.
  virtual double length() const = 0;
  // s is clamped to [0, length()].
  virtual CurvePoint at(double s) const = 0;
  virtual Vec3 start() const { return at(0.0).position; }
  virtual Vec3 end() const { return at(length()).position; }
  // Unit tangent at the end (a spline span gives it without measuring its length).
  virtual Vec3 end_tangent() const { return at(length()).tangent; }
  // Largest curvature on the curve (1/mm); exact for lines and arcs, sampled for splines.
  virtual double max_curvature() const = 0;
};

using CurvePtr = std::shared_ptr<const Curve>;

}  // namespace drycut::geometry
