#pragma once
// A curve to put knots on: a point function of a parameter t over [t_begin, t_end]. Polar curves
// r(θ) use θ in radians as t. The arc-length table turns t into arc length and back, so knots can
// be spaced evenly along the true curve.
#include <functional>
#include <vector>

#include <Eigen/Core>

namespace drycut::workload {

using Vec3 = Eigen::Vector3d;

struct CurveSource {
  std::function<Vec3(double)> point;
  double t_begin = 0.0;
  double t_end = 0.0;
};

// The polar curve x = r(θ) cos θ, y = r(θ) sin θ, z = 0 over θ in [0, 2π).
CurveSource polar_curve(std::function<double(double)> radius);

// The reference experiment's contour r(θ) = 18 + 4 cos(6θ) cos(2θ) (EXPERIMENT.md §1).
double thesis_radius(double theta);

// Cumulative arc length of a curve over [t_begin, t_end], by composite Gauss-Legendre quadrature
// of |dP/dt| (central differences), accurate to ~1e-9 relative for smooth curves.
class ArcLengthTable {
 public:
  ArcLengthTable(const CurveSource& curve, double t_begin, double t_end, int intervals = 4096);
  double total() const { return s_.back(); }
  double length_at(double t) const;
  // Inverse: the parameter at arc length s (clamped to the range).
  double parameter_at(double s) const;

 private:
  double speed(double t) const;
  const CurveSource& curve_;
  double t0_, dt_;
  std::vector<double> s_;  // arc length at t0 + i*dt
};

}  // namespace drycut::workload
