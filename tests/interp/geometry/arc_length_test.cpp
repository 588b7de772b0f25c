// Arc-length accuracy of spline spans against an independent fine polyline of the parametric
// curve, the s -> u inversion, and the derivative identities of at(s).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "geometry_test_support.hpp"
#include "interp/geometry/curve_sampler.hpp"
#include "interp/geometry/line_curve.hpp"
#include "interp/geometry/polynomial_span.hpp"
#include "interp/geometry/spline_builder.hpp"

namespace drycut::geometry {
namespace {

void check_span(const PolynomialSpan& span) {
  const double u1 = span.parameter_end();
  const auto f = [&](double u) { return span.derivatives(u).p; };
  const double ref = testing::polyline_length(f, 0, u1, 400000);
  EXPECT_NEAR(span.length() / ref, 1.0, 1e-6);
  // Inversion: the point at the reference arc length of u is P(u).
  for (double frac : {0.2, 0.5, 0.85}) {
    const double u = frac * u1;
    const double s = testing::polyline_length(f, 0, u, 200000);
    EXPECT_LT((span.at(s).position - f(u)).norm(), 1e-6 * span.length()) << frac;
  }
  for (double frac : {0.1, 0.4, 0.9}) testing::expect_consistent_derivatives(span, frac * span.length(), 1e-4);
}

TEST(ArcLength, HermiteSpanWithUnevenSpeed) {
  // Tangents of very different magnitude: the parameter speed varies by a factor of ~10.
  const PolynomialSpan span = PolynomialSpan::hermite({0, 0, 0}, {4, 1, 0}, {0.3, 0, 0}, {0, 6, 2}, 3.0);
  check_span(span);
}

TEST(ArcLength, RationalNurbsSpan) {
  auto b = make_nurbs_builder(3);
  const auto spans = testing::run_spline(*b, {{0, 0, 0}, {1, 3, 0}, {4, 3, 1}, {5, 0, 2}, {8, 1, 0}, {9, 4, 0}}, {},
                                         {1, 3, 0.2, 2.5, 1, 1});
  ASSERT_FALSE(spans.empty());
  for (const auto& s : spans) check_span(dynamic_cast<const PolynomialSpan&>(*s.curve));
}

// A polynomial span (w == 1) takes a shortcut past the quotient rule; the same curve written
// with the constant weight w == 2 (every coefficient doubled) goes through the rational
// formulas. Both must agree: positions, derivatives, length and the s -> u inversion.
TEST(ArcLength, PolynomialShortcutMatchesRationalFormulas) {
  Eigen::Matrix4d c;
  c << 1.0, 0.3, 0.7, -0.21,  //
      -2.0, 0.0, 1.9, -0.45,  //
      0.5, 0.1, 0.2, 0.05,    //
      1.0, 0.0, 0.0, 0.0;
  const PolynomialSpan poly(c, 3.0);
  Eigen::Matrix4d doubled = 2.0 * c;  // w == 2 everywhere: the same curve
  const PolynomialSpan rational(doubled, 3.0);
  EXPECT_NEAR(rational.length(), poly.length(), 1e-13 * poly.length());
  for (double frac : {0.0, 0.13, 0.5, 0.77, 1.0}) {
    const double u = frac * poly.parameter_end();
    const ParametricDerivatives a = poly.derivatives(u), b = rational.derivatives(u);
    EXPECT_LT((a.p - b.p).norm(), 1e-13);
    EXPECT_LT((a.d1 - b.d1).norm(), 1e-13 * a.d1.norm());
    EXPECT_LT((a.d2 - b.d2).norm(), 1e-12 * (1 + a.d2.norm()));
    EXPECT_LT((a.d3 - b.d3).norm(), 1e-12 * (1 + a.d3.norm()));
    const double s = frac * poly.length();
    EXPECT_NEAR(poly.parameter_at(s), rational.parameter_at(s), 1e-12);
  }
}

// The polynomial span's 5-node integrals evaluate their nodes two at a time (SIMD lanes): each
// must equal, bit for bit, the 5-point Gauss rule over the scalar speed |c1 + u(2c2 + 3u c3)|
// evaluated here one node at a time, on random spans and intervals.
TEST(ArcLength, FiveNodeSpeedsMatchOneAtATimeBitForBit) {
  std::mt19937 rng(2026);
  std::uniform_real_distribution<double> coef(-50.0, 50.0), frac(0.0, 1.0);
  constexpr double nodes[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831,
                               0.9061798459386640};
  constexpr double weights[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                                 0.4786286704993665, 0.2369268850561891};
  for (int trial = 0; trial < 2000; ++trial) {
    Eigen::Matrix4d c = Eigen::Matrix4d::Zero();
    for (int r = 0; r < 3; ++r)
      for (int k = 0; k < 4; ++k) c(r, k) = coef(rng) * std::pow(10.0, static_cast<int>(rng() % 7) - 3);
    c(3, 0) = 1.0;
    const double u_end = 0.01 + 5 * frac(rng);
    const PolynomialSpan span(c, u_end);
    // Per axis c1 + u (2 c2 + (3u) c3); the norm as (x² + y²) + z².
    const auto speed = [&](double u) {
      double d[3];
      for (int r = 0; r < 3; ++r) d[r] = c(r, 1) + u * (2.0 * c(r, 2) + (3.0 * u) * c(r, 3));
      return std::sqrt((d[0] * d[0] + d[1] * d[1]) + d[2] * d[2]);
    };
    double a = frac(rng) * u_end, b = frac(rng) * u_end;
    if (a > b) std::swap(a, b);
    const double half = 0.5 * (b - a), mid = 0.5 * (a + b);
    double sum = 0.0;
    for (int i = 0; i < 5; ++i) sum += weights[i] * speed(mid + half * nodes[i]);
    ASSERT_EQ(span.arc_length_between(a, b), sum * half) << trial;
  }
}

// A speed with a near-cusp needs many table entries (beyond those kept inside the table):
// the length still matches the polyline and the inversion stays monotone.
TEST(ArcLength, LongTableBeyondInlineEntries) {
  const PolynomialSpan span = PolynomialSpan::hermite({0, 0, 0}, {1, 0, 0}, {3, 0, 0}, {3, 0.001, 0}, 1.0);
  check_span(span);
  double last = -1;
  for (int i = 0; i <= 200; ++i) {
    const double u = span.parameter_at(span.length() * i / 200);
    EXPECT_GE(u, last);
    last = u;
  }
}

TEST(ArcLength, SplineSpanMaxCurvatureBoundsSampledCurvature) {
  const PolynomialSpan span = PolynomialSpan::hermite({0, 0, 0}, {4, 1, 0}, {1, 0, 0}, {0, 1, 0}, 4.2);
  double sampled = 0;
  for (int i = 0; i <= 1000; ++i) sampled = std::max(sampled, span.at(span.length() * i / 1000).curvature);
  EXPECT_NEAR(span.max_curvature(), sampled, 0.02 * sampled);
}

TEST(CurveSampler, EveryDsWithBothEnds) {
  const LineCurve line({0, 0, 0}, {1.005, 0, 0});
  const auto pts = sample_curve(line, 0.01);
  ASSERT_EQ(pts.size(), 102u);  // 0, 0.01 .. 1.00, and the end 1.005
  EXPECT_NEAR(pts[50].x(), 0.5, 1e-12);
  EXPECT_EQ(pts.back(), Vec3(1.005, 0, 0));
  EXPECT_EQ(sample_curve(line, 0.0).size(), 2u);
  EXPECT_EQ(sample_curve(LineCurve({1, 1, 1}, {1, 1, 1}), 0.1).size(), 1u);
}

}  // namespace
}  // namespace drycut::geometry
