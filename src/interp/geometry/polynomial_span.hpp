#pragma once
// One spline span: a (rational) cubic in homogeneous coordinates,
//   H(u) = c0 + c1 u + c2 u^2 + c3 u^3,  H = (w x, w y, w z, w),  u in [0, u_end],
// so P(u) = H.xyz / H.w. Polynomial splines (Akima, cubic) have w == 1; NURBS spans of degree
// <= 3 are rational. Evaluated by arc length through an ArcLengthTable.
#include <algorithm>

#include <Eigen/Core>

#include "interp/geometry/arc_length_table.hpp"
#include "interp/geometry/curve.hpp"

namespace drycut::geometry {

// Position and derivatives with respect to the span parameter u.
struct ParametricDerivatives {
  Vec3 p, d1, d2, d3;
};

// Largest curvature |P' x P''| / |P'|^3 of a parametric curve on [0, end], sampled at
// `samples` equal parameter steps (both ends included); `derivatives(u)` gives
// ParametricDerivatives. Used by the spans' max_curvature() (asked by cutter compensation).
template <typename DerivativesFn>
double sampled_max_curvature(const DerivativesFn& derivatives, double end, int samples) {
  double largest = 0.0;
  for (int i = 0; i <= samples; ++i) {
    const ParametricDerivatives d = derivatives(end * i / samples);
    const double v = d.d1.norm();
    if (v > 0.0) largest = std::max(largest, d.d1.cross(d.d2).norm() / (v * v * v));
  }
  return largest;
}

class PolynomialSpan final : public Curve {
 public:
  // Columns are the coefficients c0..c3 of the homogeneous polynomial (rows x, y, z, w).
  PolynomialSpan(const Eigen::Matrix4d& coefficients, double u_end);

  // Cubic Hermite span on u in [0, h]: P(0)=p0, P(h)=p1, P'(0)=m0, P'(h)=m1.
  static PolynomialSpan hermite(const Vec3& p0, const Vec3& p1, const Vec3& m0, const Vec3& m1, double h);

  double length() const override { return table().length(); }
  CurvePoint at(double s) const override;
  Vec3 start() const override { return start_point().position; }
  Vec3 end() const override { return end_point().position; }
  Vec3 end_tangent() const override { return end_point().tangent; }
  // Sampled on first use: only cutter compensation asks, and the planner's hot path builds
  // one span per spline block.
  double max_curvature() const override;

  ParametricDerivatives derivatives(double u) const;
  // Arc length between two parameters (5-node Gauss-Legendre: for short sub-intervals of a
  // smooth span, without the inversion at() needs).
  double arc_length_between(double u0, double u1) const;
  double parameter_end() const { return u_end_; }
  double parameter_at(double s) const;
  // Arc length from the start to parameter u (the inverse of parameter_at, without Newton).
  double arc_length_at(double u) const;
  // Turns parametric derivatives into the arc-length quantities of a CurvePoint.
  static CurvePoint by_arc_length(const ParametricDerivatives& d);

 private:
  // Calls f with |dP/du| (the arc-length integrand, without the higher derivatives) as a
  // callable, polynomial or rational.
  template <typename F>
  auto with_speed(F&& f) const;

  // The end points (u = 0 and u_end) evaluated on first use: the interpreter (end tangent),
  // the planner's validation (start, end), its end stations and its commit (end) ask for them,
  // 4-6 evaluations per span otherwise. The same formulas, so the same values.
  const CurvePoint& start_point() const;
  const CurvePoint& end_point() const;

  // The arc-length table, built on first use: a span is made on the interpreting thread but
  // measured on the planning thread (length, at), so an interpolating spline's main
  // construction cost goes to the planner, which waits for the interpreter on A and C splines
  // (the NURBS builder asks for the length at once: its planner is the slower thread).
  // Single-threaded use per span: the pipeline hands a span over before the planner reads it.
  const ArcLengthTable& table() const;

  Eigen::Matrix4d c_;
  double u_end_;
  bool polynomial_;  // w == 1 (Akima, cubic): P = H.xyz, no quotient rule
  mutable bool table_built_ = false;
  mutable ArcLengthTable table_;
  mutable double max_curvature_ = -1.0;  // < 0: not sampled yet
  mutable bool start_known_ = false, end_known_ = false;
  mutable CurvePoint start_point_, end_point_;
};

}  // namespace drycut::geometry
