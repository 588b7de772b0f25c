#include <gtest/gtest.h>

#include <cmath>

#include "geometry_test_support.hpp"
#include "interp/geometry/line_curve.hpp"
#include "interp/geometry/polynomial_span.hpp"
#include "interp/geometry/spline_builder.hpp"
#include "machine/alarm.hpp"

namespace drycut::geometry {
namespace {

using testing::run_spline;

// Reference NURBS by the Cox-de Boor recursion on the documented clamped knot vector
// (independent of the builder's de Boor evaluation and polynomial conversion).
struct ReferenceNurbs {
  std::vector<Vec3> ctrl;
  std::vector<double> w;
  std::vector<double> knots;
  int p;

  ReferenceNurbs(std::vector<Vec3> c, std::vector<double> weights, std::vector<double> pl, int degree)
      : ctrl(std::move(c)), w(std::move(weights)), p(degree) {
    const int n = static_cast<int>(ctrl.size()) - 1;
    for (int i = 0; i <= p; ++i) knots.push_back(0.0);
    double cum = 0;
    for (int j = 1; j <= n - p + 1; ++j) {
      cum += pl.empty() || pl[j] <= 0 ? (ctrl[j] - ctrl[j - 1]).norm() : pl[j];
      knots.push_back(cum);
    }
    for (int i = 1; i <= p; ++i) knots.push_back(cum);
  }
  double basis(int i, int k, double u) const {
    if (k == 0) {
      const bool last = u == knots.back() && knots[i + 1] == knots.back() && knots[i] < knots[i + 1];
      return (knots[i] <= u && u < knots[i + 1]) || last ? 1.0 : 0.0;
    }
    double r = 0;
    if (knots[i + k] > knots[i]) r += (u - knots[i]) / (knots[i + k] - knots[i]) * basis(i, k - 1, u);
    if (knots[i + k + 1] > knots[i + 1])
      r += (knots[i + k + 1] - u) / (knots[i + k + 1] - knots[i + 1]) * basis(i + 1, k - 1, u);
    return r;
  }
  Vec3 at(double u) const {
    Vec3 num = Vec3::Zero();
    double den = 0;
    for (size_t i = 0; i < ctrl.size(); ++i) {
      const double b = basis(static_cast<int>(i), p, u) * w[i];
      num += b * ctrl[i];
      den += b;
    }
    return num / den;
  }
};

std::vector<Vec3> polygon() {
  return {{0, 0, 0}, {3, 1, 0}, {4, 4, 1}, {2, 6, 1}, {5, 9, 0}, {9, 8, 2}, {10, 3, 1}, {14, 2, 0}};
}

double distance_to(const std::vector<SplineSpan>& spans, const Vec3& q) {
  double best = 1e300;
  for (const auto& s : spans)
    for (int i = 0; i <= 400; ++i) best = std::min(best, (s.curve->at(s.curve->length() * i / 400).position - q).norm());
  return best;
}

TEST(NurbsSpline, MatchesCoxDeBoorReferenceWithWeightsAndPL) {
  const auto pts = polygon();
  const std::vector<double> w{1, 0.5, 2, 1, 3, 0.2, 1, 1};
  const std::vector<double> pl{0, 0, 2.5, 0, 7, 0, 0, 0};  // PL on blocks 2 and 4, chords elsewhere
  for (int degree : {2, 3}) {
    auto b = make_nurbs_builder(degree);
    const auto spans = run_spline(*b, pts, {}, w, pl);
    const ReferenceNurbs ref(pts, w, pl, degree);
    const size_t n = pts.size() - 1;
    ASSERT_EQ(spans.size(), n - degree + 1);
    for (size_t k = 0; k < spans.size(); ++k) {
      EXPECT_EQ(spans[k].block_index, k + 1);
      const auto* span = dynamic_cast<const PolynomialSpan*>(spans[k].curve.get());
      ASSERT_NE(span, nullptr);
      const double a = ref.knots[degree + k], c = ref.knots[degree + k + 1];
      for (double f : {0.0, 0.2, 0.5, 0.9, 1.0}) {
        EXPECT_LT((span->derivatives(f).p - ref.at(a + f * (c - a))).norm(), 1e-10) << degree << " " << k << " " << f;
      }
    }
  }
}

TEST(NurbsSpline, InterpolatesEndsAndLeavesAlongTheControlLegs) {
  const auto pts = polygon();
  auto b = make_nurbs_builder(3);
  const auto spans = run_spline(*b, pts);
  const Curve& first = *spans.front().curve;
  const Curve& last = *spans.back().curve;
  EXPECT_LT((first.start() - pts.front()).norm(), 1e-12);
  EXPECT_LT((last.end() - pts.back()).norm(), 1e-12);
  EXPECT_LT((first.at(0).tangent - (pts[1] - pts[0]).normalized()).norm(), 1e-9);
  EXPECT_LT((last.at(last.length()).tangent - (pts[7] - pts[6]).normalized()).norm(), 1e-9);
  // Consecutive spans join with continuous tangent and curvature (C2 for distinct knots, p = 3).
  for (size_t k = 0; k + 1 < spans.size(); ++k) {
    const Curve& a = *spans[k].curve;
    const CurvePoint pa = a.at(a.length()), pc = spans[k + 1].curve->at(0);
    EXPECT_LT((pa.position - pc.position).norm(), 1e-12);
    EXPECT_LT((pa.tangent - pc.tangent).norm(), 1e-9);
    EXPECT_LT((pa.curvature_vector - pc.curvature_vector).norm(), 1e-8);
  }
}

TEST(NurbsSpline, StaysInsideTheConvexHullOfAConvexPolygon) {
  // Control points on an ellipse arc, counter-clockwise: their hull is the polygon itself.
  std::vector<Vec3> pts;
  for (int i = 0; i <= 9; ++i) pts.emplace_back(8 * std::cos(0.3 * i), 5 * std::sin(0.3 * i), 0);
  auto b = make_nurbs_builder(3);
  const auto spans = run_spline(*b, pts, {}, {1, 2, 0.3, 3, 1, 1, 0.5, 2, 1, 1});
  for (const auto& s : spans) {
    for (int i = 0; i <= 50; ++i) {
      const Vec3 q = s.curve->at(s.curve->length() * i / 50).position;
      for (size_t e = 0; e < pts.size(); ++e) {
        const Vec3& a = pts[e];
        const Vec3& c = pts[(e + 1) % pts.size()];
        const double cross = (c - a).x() * (q - a).y() - (c - a).y() * (q - a).x();
        EXPECT_GE(cross, -1e-9);
      }
    }
  }
}

// The polygon's spans unweighted and with PW=3 on every point.
std::pair<std::vector<SplineSpan>, std::vector<SplineSpan>> plain_and_equally_weighted(const std::vector<Vec3>& pts) {
  auto plain = make_nurbs_builder(3);
  auto heavy = make_nurbs_builder(3);
  auto a = run_spline(*plain, pts);
  auto c = run_spline(*heavy, pts, {}, std::vector<double>(pts.size(), 3.0));
  return {std::move(a), std::move(c)};
}

TEST(NurbsSpline, EqualWeightsEverywhereAreThePlainBSpline) {
  const auto pts = polygon();
  const auto [a, c] = plain_and_equally_weighted(pts);
  ASSERT_EQ(a.size(), c.size());
  for (size_t k = 0; k < a.size(); ++k) {
    EXPECT_NEAR(a[k].curve->length(), c[k].curve->length(), 1e-12);
    for (double f : {0.0, 0.3, 0.7, 1.0}) {
      EXPECT_LT((a[k].curve->at(f * a[k].curve->length()).position - c[k].curve->at(f * c[k].curve->length()).position).norm(), 1e-12);
    }
  }
}

TEST(NurbsSpline, EqualWeightsGiveTheSamePolynomialSpanBitForBit) {
  // Equal weights cancel in the quotient: the builder writes such spans as the polynomial
  // B spline of the points (w == 1), so PW=3 on every point is the unweighted span exactly, and
  // both match the Cox-de Boor reference; a span with a differing weight stays rational.
  const auto pts = polygon();
  const ReferenceNurbs ref(pts, std::vector<double>(pts.size(), 1.0), {}, 3);
  const auto [a, c] = plain_and_equally_weighted(pts);
  ASSERT_EQ(a.size(), c.size());
  for (size_t k = 0; k < a.size(); ++k) {
    const auto* sa = dynamic_cast<const PolynomialSpan*>(a[k].curve.get());
    const auto* sc = dynamic_cast<const PolynomialSpan*>(c[k].curve.get());
    ASSERT_TRUE(sa && sc);
    const double u0 = ref.knots[3 + k], u1 = ref.knots[4 + k];
    for (double f : {0.0, 0.25, 0.5, 0.8, 1.0}) {
      const ParametricDerivatives da = sa->derivatives(f), dc = sc->derivatives(f);
      EXPECT_EQ(da.p, dc.p);
      EXPECT_EQ(da.d1, dc.d1);
      EXPECT_EQ(da.d3, dc.d3);
      EXPECT_LT((da.p - ref.at(u0 + f * (u1 - u0))).norm(), 1e-10) << k << " " << f;
    }
    EXPECT_EQ(sa->length(), sc->length());
  }
  // One point weighted differently: the spans it shapes differ from the plain ones.
  std::vector<double> w(pts.size(), 1.0);
  w[4] = 2.0;
  auto weighted = make_nurbs_builder(3);
  const auto d = run_spline(*weighted, pts, {}, w);
  EXPECT_GT((d[2].curve->at(0.5 * d[2].curve->length()).position -
             a[2].curve->at(0.5 * a[2].curve->length()).position).norm(), 1e-3);
}

TEST(NurbsSpline, DegreeTwoDiffersFromDegreeThree) {
  const auto pts = polygon();
  auto b2 = make_nurbs_builder(2);
  auto b3 = make_nurbs_builder(3);
  const auto s2 = run_spline(*b2, pts);
  const auto s3 = run_spline(*b3, pts);
  EXPECT_EQ(s2.size(), s3.size() + 1);
  // Degree 2 hugs the polygon more closely: nearer to an interior control point.
  EXPECT_LT(distance_to(s2, pts[4]), distance_to(s3, pts[4]) - 0.1);
}

TEST(NurbsSpline, WeightAboveOnePullsTowardsItsPoint) {
  const auto pts = polygon();
  std::vector<double> w(pts.size(), 1.0);
  auto b1 = make_nurbs_builder(3);
  const double before = distance_to(run_spline(*b1, pts, {}, w), pts[4]);
  w[4] = 3.0;
  auto b3 = make_nurbs_builder(3);
  const double after = distance_to(run_spline(*b3, pts, {}, w), pts[4]);
  w[4] = 0.3;
  auto b0 = make_nurbs_builder(3);
  const double weaker = distance_to(run_spline(*b0, pts, {}, w), pts[4]);
  EXPECT_LT(after, before - 0.1);
  EXPECT_GT(weaker, before + 0.1);
}

TEST(NurbsSpline, FewPointsReduceTheDegree) {
  // Three control points with SD=3: degree 2, the quadratic Bezier curve.
  const std::vector<Vec3> p{{0, 0, 0}, {2, 4, 0}, {6, 0, 0}};
  auto b = make_nurbs_builder(3);
  const auto spans = run_spline(*b, p);
  ASSERT_EQ(spans.size(), 1u);
  const auto* span = dynamic_cast<const PolynomialSpan*>(spans[0].curve.get());
  for (double t : {0.25, 0.5, 0.8}) {
    const Vec3 bez = (1 - t) * (1 - t) * p[0] + 2 * t * (1 - t) * p[1] + t * t * p[2];
    EXPECT_LT((span->derivatives(t).p - bez).norm(), 1e-12);
  }
  // Two control points: a straight line.
  auto l = make_nurbs_builder(3);
  const auto line = run_spline(*l, {{0, 0, 0}, {0, 3, 4}});
  ASSERT_EQ(line.size(), 1u);
  EXPECT_NE(dynamic_cast<const LineCurve*>(line[0].curve.get()), nullptr);
  EXPECT_NEAR(line[0].curve->length(), 5, 1e-12);
}

TEST(NurbsSpline, StreamsWithBoundedLookAhead) {
  auto b = make_nurbs_builder(3);
  SplineSpan span;
  size_t popped = 0;
  for (int i = 0; i < 100; ++i) {
    b->add_point({1.0 * i, std::sin(0.3 * i), 0}, 1, 0);
    while (b->pop_span(span)) {
      EXPECT_EQ(span.block_index, ++popped);
    }
    if (i >= 4) {
      EXPECT_EQ(popped, static_cast<size_t>(i - 4));  // span j final at point j+2p-2 = j+4
    }
  }
  b->finish({});
  while (b->pop_span(span)) ++popped;
  EXPECT_EQ(popped, 99u - 3 + 1);
}

TEST(NurbsSpline, BadValuesAreAlarm12160) {
  auto expect_12160 = [](auto&& f) {
    try {
      f();
      ADD_FAILURE() << "no alarm";
    } catch (const AlarmError& e) {
      EXPECT_EQ(e.alarm().number, 12160);
    }
  };
  expect_12160([] { make_nurbs_builder(4); });
  expect_12160([] { make_nurbs_builder(3)->add_point({0, 0, 0}, 3.5, 0); });
  expect_12160([] { make_nurbs_builder(3)->add_point({0, 0, 0}, -1, 0); });
  expect_12160([] {
    auto b = make_nurbs_builder(2);
    b->add_point({0, 0, 0}, 0.0, 0);  // PW=0 on the start point leaves the curve undefined there
    b->add_point({1, 0, 0}, 1, 0);
    b->add_point({2, 1, 0}, 1, 0);
    b->finish({});
  });
}

}  // namespace
}  // namespace drycut::geometry
