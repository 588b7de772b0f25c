#include "interp/geometry/polynomial_curve.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace drycut::geometry {
namespace {
constexpr int kCurvatureSamples = 32;  // equal parameter steps for max_curvature()
}  // namespace

PolynomialCurve::PolynomialCurve(const Coefficients& coefficients, double p_end) : a_(coefficients), p_end_(p_end) {
  table_ = ArcLengthTable([this](double p) { return speed(p); }, 0.0, p_end_);
}

PolynomialCurve PolynomialCurve::through(const Vec3& start, const Vec3& end,
                                         const Eigen::Matrix<double, 3, 4>& higher, double p_end) {
  Coefficients a = Coefficients::Zero();
  a.col(0) = start;
  a.rightCols<4>() = higher;
  // f(PL) = end: a1 = (end - a0 - a2 PL^2 - ... - a5 PL^5) / PL.
  Vec3 rest = end - start;
  double power = p_end;
  for (int k = 2; k <= 5; ++k) {
    power *= p_end;
    rest -= a.col(k) * power;
  }
  a.col(1) = rest / p_end;
  return PolynomialCurve(a, p_end);
}

ParametricDerivatives PolynomialCurve::derivatives(double p) const {
  // Term by term: d^j/dp^j of a_k p^k is k!/(k-j)! a_k p^(k-j).
  std::array<double, 6> power{1.0, p, p * p, p * p * p, p * p * p * p, p * p * p * p * p};
  ParametricDerivatives d;
  d.p = d.d1 = d.d2 = d.d3 = Vec3::Zero();
  for (int k = 0; k <= 5; ++k) {
    const auto u = static_cast<size_t>(k);
    const double n = k;
    d.p += a_.col(k) * power[u];
    if (k >= 1) d.d1 += (n * power[u - 1]) * a_.col(k);
    if (k >= 2) d.d2 += (n * (n - 1) * power[u - 2]) * a_.col(k);
    if (k >= 3) d.d3 += (n * (n - 1) * (n - 2) * power[u - 3]) * a_.col(k);
  }
  return d;
}

CurvePoint PolynomialCurve::at(double s) const {
  return PolynomialSpan::by_arc_length(derivatives(table_.parameter_at([this](double p) { return speed(p); }, s)));
}

double PolynomialCurve::max_curvature() const {
  if (max_curvature_ < 0.0)
    max_curvature_ = sampled_max_curvature([this](double p) { return derivatives(p); }, p_end_, kCurvatureSamples);
  return max_curvature_;
}

}  // namespace drycut::geometry
