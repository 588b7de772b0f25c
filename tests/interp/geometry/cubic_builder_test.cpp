#include <gtest/gtest.h>

#include <cmath>

#include "geometry_test_support.hpp"
#include "interp/geometry/cubic_spline_tangents.hpp"
#include "interp/geometry/polynomial_span.hpp"
#include "interp/geometry/spline_builder.hpp"
#include "machine/alarm.hpp"

namespace drycut::geometry {
namespace {

using testing::run_spline;

std::vector<Vec3> wiggle(int n) {
  std::vector<Vec3> pts;
  double x = 0;
  for (int i = 0; i < n; ++i) {
    pts.emplace_back(x, 3 * std::sin(0.5 * x) + 0.3 * (i % 2), 0.1 * i);
    x += 1.0 + 0.5 * (i % 3);
  }
  return pts;
}

// The one-tangent solve (two half sweeps meeting at row j) against the full Thomas solve, for
// every row, every pair of end conditions and systems of 2..9 intervals.
TEST(CubicSplineTangentAt, EqualsTheFullSolveAtEveryPoint) {
  using Kind = TangentCondition::Kind;
  const auto pts = wiggle(10);
  const std::vector<TangentCondition> ends{
      {Kind::Natural, Vec3::Zero()}, {Kind::Clamped, Vec3(0.6, -0.8, 0.0)}, {Kind::NotAKnot, Vec3::Zero()}};
  for (size_t count = 3; count <= pts.size(); ++count) {
    const std::span<const Vec3> p(pts.data(), count);
    std::vector<double> h;
    for (size_t i = 1; i < count; ++i) h.push_back((pts[i] - pts[i - 1]).norm());
    for (const auto& b : ends) {
      for (const auto& e : ends) {
        const auto full = cubic_spline_tangents(p, h, b, e);
        for (size_t j = 0; j < count; ++j) {
          const Vec3 one = cubic_spline_tangent_at(p, h, b, e, j);
          EXPECT_LT((one - full[j]).norm(), 1e-12 * (1.0 + full[j].norm()))
              << count << " points, row " << j;
        }
      }
    }
  }
}

TEST(CubicSpline, GlobalPassesThroughPointsAndIsC2) {
  const auto pts = wiggle(15);
  auto b = make_cubic_builder({}, 0);
  const auto spans = run_spline(*b, pts);
  ASSERT_EQ(spans.size(), pts.size() - 1);
  const double h = 1e-4;
  for (size_t k = 0; k < spans.size(); ++k) {
    EXPECT_EQ(spans[k].block_index, k + 1);
    EXPECT_LT((spans[k].curve->start() - pts[k]).norm(), 1e-12);
    EXPECT_LT((spans[k].curve->end() - pts[k + 1]).norm(), 1e-12);
    if (k + 1 == spans.size()) break;
    const Curve& a = *spans[k].curve;
    const Curve& c = *spans[k + 1].curve;
    const CurvePoint pa = a.at(a.length()), pc = c.at(0);
    EXPECT_LT((pa.tangent - pc.tangent).norm(), 1e-9);
    EXPECT_LT((pa.curvature_vector - pc.curvature_vector).norm(), 1e-9) << "joint " << k + 1;
    // Curvature vector by finite differences of tangents on either side of the joint.
    const Vec3 k_left = (a.at(a.length()).tangent - a.at(a.length() - h).tangent) / h;
    const Vec3 k_right = (c.at(h).tangent - c.at(0).tangent) / h;
    EXPECT_LT((k_left - k_right).norm(), 1e-3) << "joint " << k + 1;
  }
}

TEST(CubicSpline, NaturalEndsHaveZeroCurvature) {
  const auto pts = wiggle(9);
  for (int window : {0, 8}) {
    auto b = make_cubic_builder({EndCondition::Natural, {}}, window);
    const auto spans = run_spline(*b, pts, {EndCondition::Natural, {}});
    EXPECT_LT(spans.front().curve->at(0).curvature, 1e-10) << window;
    EXPECT_LT(spans.back().curve->at(spans.back().curve->length()).curvature, 1e-10) << window;
    EXPECT_GT(spans[3].curve->max_curvature(), 0.01);
  }
}

TEST(CubicSpline, TangentEndsFollowTheGivenDirection) {
  const auto pts = wiggle(9);
  const Vec3 t0 = Vec3(0, 1, 0), t1 = Vec3(1, 0, -1).normalized();
  for (int window : {0, 8}) {
    auto b = make_cubic_builder({EndCondition::Tangent, t0}, window);
    const auto spans = run_spline(*b, pts, {EndCondition::Tangent, t1});
    EXPECT_LT((spans.front().curve->at(0).tangent - t0).norm(), 1e-12);
    EXPECT_LT((spans.back().curve->at(spans.back().curve->length()).tangent - t1).norm(), 1e-12);
  }
}

// Not-a-knot at both ends with four points: one cubic per axis over the chord-length parameter,
// i.e. the Lagrange cubic through the four points.
TEST(CubicSpline, NotAKnotWithFourPointsIsTheLagrangeCubic) {
  const std::vector<Vec3> pts{{0, 0, 0}, {2, 1, 0}, {3, 3, 1}, {3, 6, 2}};
  std::vector<double> t{0};
  for (size_t i = 1; i < pts.size(); ++i) t.push_back(t.back() + (pts[i] - pts[i - 1]).norm());
  auto lagrange = [&](double x) {
    Vec3 r = Vec3::Zero();
    for (size_t i = 0; i < 4; ++i) {
      double w = 1;
      for (size_t j = 0; j < 4; ++j) if (j != i) w *= (x - t[j]) / (t[i] - t[j]);
      r += w * pts[i];
    }
    return r;
  };
  for (int window : {0, 8}) {
  auto b = make_cubic_builder({EndCondition::Auto, {}}, window);
  const auto spans = run_spline(*b, pts, {EndCondition::Auto, {}});
  ASSERT_EQ(spans.size(), 3u);
  for (size_t k = 0; k < 3; ++k) {
    const auto* span = dynamic_cast<const PolynomialSpan*>(spans[k].curve.get());
    ASSERT_NE(span, nullptr);
    EXPECT_NEAR(span->parameter_end(), t[k + 1] - t[k], 1e-12);
    for (double f : {0.0, 0.3, 0.6, 1.0}) {
      const double u = f * span->parameter_end();
      EXPECT_LT((span->derivatives(u).p - lagrange(t[k] + u)).norm(), 1e-10) << window << " " << k << " " << f;
    }
  }
  }
  // Three points with not-a-knot at both ends: the parabola (Lagrange quadratic).
  auto b3 = make_cubic_builder({EndCondition::Auto, {}}, 0);
  const std::vector<Vec3> p3{{0, 0, 0}, {1, 2, 0}, {4, 3, 0}};
  const auto s3 = run_spline(*b3, p3, {EndCondition::Auto, {}});
  const double h0 = (p3[1] - p3[0]).norm(), t2 = h0 + (p3[2] - p3[1]).norm();
  auto quad = [&](double x) {
    return Vec3(p3[0] * ((x - h0) * (x - t2) / (h0 * t2)) + p3[1] * (x * (x - t2) / (h0 * (h0 - t2))) +
                p3[2] * (x * (x - h0) / (t2 * (t2 - h0))));
  };
  const auto* s1 = dynamic_cast<const PolynomialSpan*>(s3[1].curve.get());
  EXPECT_LT((s1->derivatives(0.4 * s1->parameter_end()).p - quad(h0 + 0.4 * s1->parameter_end())).norm(), 1e-10);
}

TEST(CubicSpline, PointsOnALineGiveTheLine) {
  const Vec3 o(1, 2, 3), dir = Vec3(2, -1, 2).normalized();
  std::vector<Vec3> pts;
  for (double d : {0.0, 0.5, 2.0, 2.2, 5.0, 9.0, 9.5}) pts.push_back(o + d * dir);
  for (int window : {0, 8}) {
    auto b = make_cubic_builder({EndCondition::Natural, {}}, window);
    const auto spans = run_spline(*b, pts);
    double total = 0;
    for (const auto& s : spans) {
      total += s.curve->length();
      for (double f : {0.1, 0.5, 0.9}) {
        const Vec3 p = s.curve->at(f * s.curve->length()).position - o;
        EXPECT_LT((p - p.dot(dir) * dir).norm(), 1e-12);
      }
      EXPECT_LT(s.curve->max_curvature(), 1e-9);
    }
    EXPECT_NEAR(total, 9.5, 1e-9);
  }
}

TEST(CubicSpline, WindowedIsC1AndCloseToGlobalInTheMiddleOfALongRun) {
  const auto pts = wiggle(120);
  auto g = make_cubic_builder({}, 0);
  auto w = make_cubic_builder({}, 8);
  const auto global = run_spline(*g, pts);
  const auto windowed = run_spline(*w, pts);
  ASSERT_EQ(global.size(), windowed.size());
  double worst = 0;
  for (size_t k = 20; k < 100; ++k) {
    for (double f : {0.25, 0.5, 0.75}) {
      const double d = (global[k].curve->at(f * global[k].curve->length()).position -
                        windowed[k].curve->at(f * windowed[k].curve->length()).position).norm();
      worst = std::max(worst, d);
    }
    const Curve& a = *windowed[k].curve;
    EXPECT_LT((a.at(a.length()).tangent - windowed[k + 1].curve->at(0).tangent).norm(), 1e-9);
  }
  std::cout << "windowed (8) vs global cubic, middle spans: max distance " << worst << " mm\n";
  EXPECT_LT(worst, 5e-3);  // point spacing 1..2 mm, amplitude 3 mm
  EXPECT_GT(worst, 0.0);   // the window really is a window
}

TEST(CubicSpline, WindowedStreamsGlobalWaitsForTheEnd) {
  const auto pts = wiggle(40);
  auto w = make_cubic_builder({}, 8);
  auto g = make_cubic_builder({}, 0);
  SplineSpan span;
  size_t popped_w = 0, popped_g = 0;
  for (const auto& p : pts) {
    w->add_point(p, 1, 0);
    g->add_point(p, 1, 0);
    while (w->pop_span(span)) ++popped_w;
    while (g->pop_span(span)) ++popped_g;
  }
  EXPECT_GE(popped_w, pts.size() - 7);
  EXPECT_EQ(popped_g, 0u);
}

TEST(CubicSpline, RepeatedPointOwnsNoSpanAndBadPointIsAlarm) {
  auto b = make_cubic_builder({}, 8);
  const auto spans = run_spline(*b, {{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {2, 1, 0}});
  ASSERT_EQ(spans.size(), 2u);
  EXPECT_EQ(spans[1].block_index, 3u);
  auto bad = make_cubic_builder({}, 8);
  EXPECT_THROW(bad->add_point({0, std::numeric_limits<double>::infinity(), 0}, 1, 0), AlarmError);
}

}  // namespace
}  // namespace drycut::geometry
