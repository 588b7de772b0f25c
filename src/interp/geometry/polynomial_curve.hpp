#pragma once
// The curve of a POLY block (PGA Fundamentals, "Polynomial interpolation (POLY, PO, PL)"): each
// axis is a polynomial of degree <= 5 in the parameter p in [0, PL],
//   f(p) = a0 + a1 p + a2 p^2 + a3 p^3 + a4 p^4 + a5 p^5,
// evaluated by arc length through an ArcLengthTable.
#include <Eigen/Core>

#include "interp/geometry/arc_length_table.hpp"
#include "interp/geometry/curve.hpp"
#include "interp/geometry/polynomial_span.hpp"

namespace drycut::geometry {

class PolynomialCurve final : public Curve {
 public:
  using Coefficients = Eigen::Matrix<double, 3, 6>;  // rows x, y, z; columns a0 .. a5

  PolynomialCurve(const Coefficients& coefficients, double p_end);

  // The polynomial through `start` (p = 0) and `end` (p = p_end) with the higher coefficients
  // a2..a5 given per axis: a0 = start, a1 follows from the end point.
  static PolynomialCurve through(const Vec3& start, const Vec3& end,
                                 const Eigen::Matrix<double, 3, 4>& higher, double p_end);

  double length() const override { return table_.length(); }
  CurvePoint at(double s) const override;
  Vec3 start() const override { return a_.col(0); }
  Vec3 end() const override { return derivatives(p_end_).p; }
  double max_curvature() const override;

  ParametricDerivatives derivatives(double p) const;

 private:
  double speed(double p) const { return derivatives(p).d1.norm(); }

  Coefficients a_;
  double p_end_;
  ArcLengthTable table_;
  mutable double max_curvature_ = -1.0;  // < 0: not sampled yet
};

}  // namespace drycut::geometry
