#include "interp/geometry/polynomial_span.hpp"

#include <algorithm>
#include <array>
#include <Eigen/Geometry>
#include <cmath>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace drycut::geometry {
namespace {
// Curvature is sampled at this many equal parameter steps for max_curvature().
constexpr int kCurvatureSamples = 32;

// |dP/du| of a polynomial span (w == 1): |H'.xyz|.
inline double polynomial_speed(const Eigen::Matrix4d& c, double u) {
  const auto c1 = c.col(1).head<3>(), c2 = c.col(2).head<3>(), c3 = c.col(3).head<3>();
  return (c1 + u * (2.0 * c2 + 3.0 * u * c3)).norm();
}

#if defined(__SSE2__)
// polynomial_speed at two parameters, one per SSE2 lane: each lane runs the scalar function's
// operations in its order — per axis (3u)·c3 + 2·c2, times u, plus c1, squared; (x² + y²) + z²;
// the correctly rounded square root — so the values are the same bit for bit.
inline void polynomial_speed_pair(const Eigen::Matrix4d& c, double ua, double ub, double& va, double& vb) {
  const __m128d u = _mm_set_pd(ub, ua);
  const __m128d u3 = _mm_mul_pd(_mm_set1_pd(3.0), u);
  __m128d sum = _mm_setzero_pd();
  for (int k = 0; k < 3; ++k) {
    const __m128d t = _mm_add_pd(_mm_mul_pd(u3, _mm_set1_pd(c(k, 3))), _mm_set1_pd(2.0 * c(k, 2)));
    const __m128d d = _mm_add_pd(_mm_mul_pd(u, t), _mm_set1_pd(c(k, 1)));
    sum = k == 0 ? _mm_mul_pd(d, d) : _mm_add_pd(sum, _mm_mul_pd(d, d));
  }
  const __m128d r = _mm_sqrt_pd(sum);
  va = _mm_cvtsd_f64(r);
  vb = _mm_cvtsd_f64(_mm_unpackhi_pd(r, r));
}
#endif

// The polynomial speed for the arc-length rules; five() serves a 5-node Gauss rule (two
// nodes per SIMD vector: about half the instructions of five calls).
struct PolynomialSpeed {
  const Eigen::Matrix4d& c;
  double operator()(double u) const { return polynomial_speed(c, u); }
  void five(const std::array<double, 5>& u, std::array<double, 5>& out) const {
#if defined(__SSE2__)
    polynomial_speed_pair(c, u[0], u[1], out[0], out[1]);
    polynomial_speed_pair(c, u[2], u[3], out[2], out[3]);
    out[4] = polynomial_speed(c, u[4]);
#else
    for (size_t i = 0; i < u.size(); ++i) out[i] = polynomial_speed(c, u[i]);
#endif
  }
};

// |dP/du| of a rational span: d(A/w)/du = (A' w - A w') / w^2.
inline double rational_speed(const Eigen::Matrix4d& c, double u) {
  const Eigen::Vector4d h0 = c.col(0) + u * (c.col(1) + u * (c.col(2) + u * c.col(3)));
  const Eigen::Vector4d h1 = c.col(1) + u * (2.0 * c.col(2) + 3.0 * u * c.col(3));
  return (h1.head<3>() * h0(3) - h0.head<3>() * h1(3)).norm() / (h0(3) * h0(3));
}
}  // namespace

// Calls f with the span's speed function, resolved once (the quadratures inline it).
template <typename F>
auto PolynomialSpan::with_speed(F&& f) const {
  if (polynomial_) return f(PolynomialSpeed{c_});
  return f([this](double u) { return rational_speed(c_, u); });
}

PolynomialSpan::PolynomialSpan(const Eigen::Matrix4d& coefficients, double u_end)
    : c_(coefficients),
      u_end_(u_end),
      polynomial_(c_(3, 0) == 1.0 && c_(3, 1) == 0.0 && c_(3, 2) == 0.0 && c_(3, 3) == 0.0) {}

const ArcLengthTable& PolynomialSpan::table() const {
  if (!table_built_) {
    table_ = with_speed([this](const auto& speed) { return ArcLengthTable(speed, 0.0, u_end_); });
    table_built_ = true;
  }
  return table_;
}

double PolynomialSpan::max_curvature() const {
  if (max_curvature_ < 0.0)
    max_curvature_ = sampled_max_curvature([this](double u) { return derivatives(u); }, u_end_, kCurvatureSamples);
  return max_curvature_;
}

PolynomialSpan PolynomialSpan::hermite(const Vec3& p0, const Vec3& p1, const Vec3& m0, const Vec3& m1,
                                       double h) {
  Eigen::Matrix4d c = Eigen::Matrix4d::Zero();
  const Vec3 delta = (p1 - p0) / h;
  c.block<3, 1>(0, 0) = p0;
  c.block<3, 1>(0, 1) = m0;
  c.block<3, 1>(0, 2) = (3.0 * delta - 2.0 * m0 - m1) / h;
  c.block<3, 1>(0, 3) = (m0 + m1 - 2.0 * delta) / (h * h);
  c(3, 0) = 1.0;
  return PolynomialSpan(c, h);
}

ParametricDerivatives PolynomialSpan::derivatives(double u) const {
  if (polynomial_) {
    // w == 1: the general formulas below with w = 1, w' = w'' = w''' = 0 (the same values).
    ParametricDerivatives d;
    const auto c0 = c_.col(0).head<3>(), c1 = c_.col(1).head<3>();
    const auto c2 = c_.col(2).head<3>(), c3 = c_.col(3).head<3>();
    d.p = c0 + u * (c1 + u * (c2 + u * c3));
    d.d1 = c1 + u * (2.0 * c2 + 3.0 * u * c3);
    d.d2 = 2.0 * c2 + 6.0 * u * c3;
    d.d3 = 6.0 * c3;
    return d;
  }
  const Eigen::Vector4d h0 = c_.col(0) + u * (c_.col(1) + u * (c_.col(2) + u * c_.col(3)));
  const Eigen::Vector4d h1 = c_.col(1) + u * (2.0 * c_.col(2) + 3.0 * u * c_.col(3));
  const Eigen::Vector4d h2 = 2.0 * c_.col(2) + 6.0 * u * c_.col(3);
  const Eigen::Vector4d h3 = 6.0 * c_.col(3);
  ParametricDerivatives d;
  const double w = h0(3), w1 = h1(3), w2 = h2(3), w3 = h3(3);
  // Leibniz on A = w P: A' = w'P + wP', A'' = w''P + 2w'P' + wP'', A''' = ...
  d.p = h0.head<3>() / w;
  d.d1 = (h1.head<3>() - w1 * d.p) / w;
  d.d2 = (h2.head<3>() - 2.0 * w1 * d.d1 - w2 * d.p) / w;
  d.d3 = (h3.head<3>() - 3.0 * w1 * d.d2 - 3.0 * w2 * d.d1 - w3 * d.p) / w;
  return d;
}

double PolynomialSpan::arc_length_between(double u0, double u1) const {
  return with_speed([&](const auto& speed) { return ArcLengthTable::gauss5(speed, u0, u1); });
}

double PolynomialSpan::arc_length_at(double u) const {
  return with_speed([&](const auto& speed) { return table().length_at(speed, u); });
}

double PolynomialSpan::parameter_at(double s) const {
  return with_speed([&](const auto& speed) { return table().parameter_at(speed, s); });
}

CurvePoint PolynomialSpan::by_arc_length(const ParametricDerivatives& d) {
  CurvePoint out;
  out.position = d.p;
  const double v = d.d1.norm();
  if (!(v > 1e-300)) {
    // Stationary parameter point: the direction of motion is that of the first non-zero derivative.
    const Vec3 dir = d.d2.norm() > 0.0 ? d.d2 : d.d3;
    out.tangent = dir.norm() > 0.0 ? Vec3(dir.normalized()) : Vec3(Vec3::UnitX());
    return out;
  }
  // Chain rule with u' = du/ds = 1/v:  P_s = P' u',  P_ss = P'' u'^2 + P' u'',
  // P_sss = P''' u'^3 + 3 P'' u' u'' + P' u''', where v' = dv/du = (P'.P'')/v.
  const double v1 = d.d1.dot(d.d2) / v;
  const double v2 = (d.d2.squaredNorm() + d.d1.dot(d.d3)) / v - v1 * v1 / v;
  const double up = 1.0 / v;
  const double upp = -v1 / (v * v * v);
  const double uppp = (-v2 / (v * v * v) + 3.0 * v1 * v1 / (v * v * v * v)) / v;
  out.tangent = d.d1 * up;
  out.curvature_vector = d.d2 * (up * up) + d.d1 * upp;
  out.curvature_rate = d.d3 * (up * up * up) + 3.0 * d.d2 * (up * upp) + d.d1 * uppp;
  out.curvature = out.curvature_vector.norm();
  out.curvature_derivative =
      out.curvature > 0.0 ? out.curvature_vector.dot(out.curvature_rate) / out.curvature : 0.0;
  return out;
}

// parameter_at(s) is u = 0 for s <= 0 (and for a table of one entry: a span of no length) and
// the table's last parameter, u_end itself, for s >= length: those are the cached end points.
CurvePoint PolynomialSpan::at(double s) const {
  if (table().size() < 2 || s <= 0.0) return start_point();
  if (s >= length()) return end_point();
  return by_arc_length(derivatives(parameter_at(s)));
}

const CurvePoint& PolynomialSpan::start_point() const {
  if (!start_known_) {
    start_point_ = by_arc_length(derivatives(0.0));
    start_known_ = true;
  }
  return start_point_;
}

const CurvePoint& PolynomialSpan::end_point() const {
  if (!end_known_) {
    end_point_ = by_arc_length(derivatives(u_end_));
    end_known_ = true;
  }
  return end_point_;
}

}  // namespace drycut::geometry
