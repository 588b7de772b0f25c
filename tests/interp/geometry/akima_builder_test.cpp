#include <gtest/gtest.h>

#include <cmath>

#include "geometry_test_support.hpp"
#include "interp/geometry/spline_builder.hpp"
#include "machine/alarm.hpp"

namespace drycut::geometry {
namespace {

using testing::run_spline;

// An uneven, wiggly 3-D point set.
std::vector<Vec3> wiggle(int n) {
  std::vector<Vec3> pts;
  double x = 0;
  for (int i = 0; i < n; ++i) {
    pts.emplace_back(x, 3 * std::sin(0.7 * i) + 0.5 * (i % 3), 0.2 * i);
    x += 1.0 + 0.6 * (i % 4);
  }
  return pts;
}

TEST(AkimaSpline, PassesThroughEveryPointWithOneSpanPerBlock) {
  const auto pts = wiggle(12);
  auto b = make_akima_builder({});
  const auto spans = run_spline(*b, pts);
  ASSERT_EQ(spans.size(), pts.size() - 1);
  for (size_t k = 0; k < spans.size(); ++k) {
    EXPECT_EQ(spans[k].block_index, k + 1);
    EXPECT_LT((spans[k].curve->start() - pts[k]).norm(), 1e-12);
    EXPECT_LT((spans[k].curve->end() - pts[k + 1]).norm(), 1e-12);
  }
}

TEST(AkimaSpline, TangentContinuousAtInteriorPoints) {
  const auto pts = wiggle(12);
  auto b = make_akima_builder({});
  const auto spans = run_spline(*b, pts);
  const double h = 1e-6;
  for (size_t k = 0; k + 1 < spans.size(); ++k) {
    const Curve& a = *spans[k].curve;
    const Curve& c = *spans[k + 1].curve;
    EXPECT_LT((a.at(a.length()).tangent - c.at(0).tangent).norm(), 1e-9) << "joint " << k + 1;
    // Same by one-sided finite differences of positions.
    const Vec3 left = (a.at(a.length()).position - a.at(a.length() - h).position) / h;
    const Vec3 right = (c.at(h).position - c.at(0).position) / h;
    EXPECT_LT((left - right).norm(), 1e-4) << "joint " << k + 1;
  }
}

TEST(AkimaSpline, KeepsAStraightStretchStraight) {
  // Three collinear points followed by a bend: Akima gives the flat part the flat slope
  // (no overshoot), here for the first two spans.
  const std::vector<Vec3> pts{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 1, 0}, {4, 2, 0}, {5, 2, 0}};
  auto b = make_akima_builder({});
  const auto spans = run_spline(*b, pts);
  for (int k = 0; k < 1; ++k) {
    for (double f : {0.25, 0.5, 0.75}) {
      EXPECT_NEAR(spans[k].curve->at(f * spans[k].curve->length()).position.y(), 0.0, 1e-12);
    }
  }
  EXPECT_LT((spans[1].curve->at(0).tangent - Vec3(1, 0, 0)).norm(), 1e-12);
}

TEST(AkimaSpline, MovingOnePointChangesOnlyNearbySpans) {
  auto pts = wiggle(24);
  auto b1 = make_akima_builder({});
  const auto before = run_spline(*b1, pts);
  pts[12] += Vec3(0.5, -0.7, 0.3);
  auto b2 = make_akima_builder({});
  const auto after = run_spline(*b2, pts);
  ASSERT_EQ(before.size(), after.size());
  // Tangents at points 10..14 depend on point 12, so spans ending at 10..15 change.
  for (size_t k = 0; k < before.size(); ++k) {
    const size_t end_point = k + 1;
    const double diff = (before[k].curve->at(0.5 * before[k].curve->length()).position -
                         after[k].curve->at(0.5 * after[k].curve->length()).position).norm();
    if (end_point < 10 || end_point > 15) {
      EXPECT_EQ(diff, 0.0) << "span " << end_point;
    } else {
      EXPECT_GT(diff, 1e-6) << "span " << end_point;
    }
  }
}

TEST(AkimaSpline, EndConditions) {
  const auto pts = wiggle(8);
  const Vec3 t0 = Vec3(1, 1, 0).normalized(), t1 = Vec3(0, -1, 1).normalized();
  auto tan = make_akima_builder({EndCondition::Tangent, t0});
  const auto s_tan = run_spline(*tan, pts, {EndCondition::Tangent, t1});
  EXPECT_LT((s_tan.front().curve->at(0).tangent - t0).norm(), 1e-12);
  const Curve& last = *s_tan.back().curve;
  EXPECT_LT((last.at(last.length()).tangent - t1).norm(), 1e-12);

  auto nat = make_akima_builder({EndCondition::Natural, {}});
  const auto s_nat = run_spline(*nat, pts, {EndCondition::Natural, {}});
  EXPECT_LT(s_nat.front().curve->at(0).curvature, 1e-9);
  EXPECT_LT(s_nat.back().curve->at(s_nat.back().curve->length()).curvature, 1e-9);

  // BAUTO: the start tangent is that of the parabola through the first three points, with
  // parameter 0, h0, h0+h1 (chord lengths). Lagrange derivative at 0, computed here by hand.
  auto aut = make_akima_builder({EndCondition::Auto, {}});
  const auto s_aut = run_spline(*aut, pts, {EndCondition::Auto, {}});
  const double h0 = (pts[1] - pts[0]).norm(), h1 = (pts[2] - pts[1]).norm(), t2 = h0 + h1;
  const Vec3 d = pts[0] * (-(h0 + t2) / (h0 * t2)) + pts[1] * (t2 / (h0 * (t2 - h0))) +
                 pts[2] * (-h0 / (t2 * (t2 - h0)));
  EXPECT_LT((s_aut.front().curve->at(0).tangent - d.normalized()).norm(), 1e-12);
}

TEST(AkimaSpline, SpansAreFinalBeforeTheRunEnds) {
  auto b = make_akima_builder({});
  SplineSpan span;
  const auto pts = wiggle(50);
  size_t popped = 0;
  for (const auto& p : pts) {
    b->add_point(p, 1.0, 0.0);
    while (b->pop_span(span)) ++popped;
  }
  EXPECT_GE(popped, pts.size() - 4);  // only the last few wait for the end condition
  b->finish({});
  while (b->pop_span(span)) ++popped;
  EXPECT_EQ(popped, pts.size() - 1);
}

TEST(AkimaSpline, ShortRunsAndRepeatedPoints) {
  auto b = make_akima_builder({});
  const auto two = run_spline(*b, {{0, 0, 0}, {3, 4, 0}});
  ASSERT_EQ(two.size(), 1u);
  EXPECT_NEAR(two[0].curve->length(), 5.0, 1e-9);  // natural ends: the straight line
  auto one = make_akima_builder({});
  EXPECT_TRUE(run_spline(*one, {{1, 2, 3}}).empty());
  auto rep = make_akima_builder({});
  const auto spans = run_spline(*rep, {{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {2, 1, 0}, {3, 1, 0}});
  ASSERT_EQ(spans.size(), 3u);
  EXPECT_EQ(spans[0].block_index, 1u);
  EXPECT_EQ(spans[1].block_index, 3u);  // block 2 repeats point 1: no span
  EXPECT_EQ(spans[2].block_index, 4u);
}

TEST(AkimaSpline, NonFinitePointIsAlarm12160) {
  auto b = make_akima_builder({});
  b->add_point({0, 0, 0}, 1, 0);
  try {
    b->add_point({std::nan(""), 0, 0}, 1, 0);
    FAIL() << "no alarm";
  } catch (const AlarmError& e) {
    EXPECT_EQ(e.alarm().number, 12160);
  }
}

}  // namespace
}  // namespace drycut::geometry
