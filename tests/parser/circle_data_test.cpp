#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

#include "parser/circle_data.hpp"

namespace drycut::parser {
namespace {

using P = std::array<double, 2>;

TEST(CircleData, ThreePointsGiveTheCircumcircle) {
  // Centre (1, 2), radius 5: points at 0, 90 and 180 degrees.
  const std::array<P, 3> pts{P{6, 2}, P{1, 7}, P{-4, 2}};
  const auto c = circle_through_points(pts);
  ASSERT_TRUE(c.has_value());
  EXPECT_NEAR(c->centre_x, 1.0, 1e-12);
  EXPECT_NEAR(c->centre_y, 2.0, 1e-12);
  EXPECT_NEAR(c->radius, 5.0, 1e-12);
}

TEST(CircleData, ArbitraryPointsOnACircleAreFoundAgain) {
  // Three points at 10, 130 and 250 degrees on centre (-3, 4), radius 2.5.
  std::array<P, 3> pts{};
  for (int k = 0; k < 3; ++k) {
    const double a = (10.0 + 120.0 * k) * std::numbers::pi / 180.0;
    pts[static_cast<size_t>(k)] = P{-3 + 2.5 * std::cos(a), 4 + 2.5 * std::sin(a)};
  }
  const auto c = circle_through_points(pts);
  ASSERT_TRUE(c.has_value());
  EXPECT_NEAR(c->centre_x, -3.0, 1e-12);
  EXPECT_NEAR(c->centre_y, 4.0, 1e-12);
  EXPECT_NEAR(c->radius, 2.5, 1e-12);
}

TEST(CircleData, FourPointsOfOneCircleGiveThatCircle) {
  const std::array<P, 4> pts{P{10, 0}, P{0, 10}, P{-10, 0}, P{0, -10}};
  const auto c = circle_through_points(pts);
  ASSERT_TRUE(c.has_value());
  EXPECT_NEAR(c->centre_x, 0.0, 1e-12);
  EXPECT_NEAR(c->centre_y, 0.0, 1e-12);
  EXPECT_NEAR(c->radius, 10.0, 1e-12);
}

TEST(CircleData, FourPointsOffTheCircleAreAveraged) {
  // (10,0), (0,10), (-10,0) lie on r = 10 about the origin, (0,-12) does not. Expected: the mean of
  // the four triples' circumcentres, each solved here as the 2x2 system |C-a| = |C-b| = |C-c|.
  const std::array<P, 4> pts{P{10, 0}, P{0, 10}, P{-10, 0}, P{0, -12}};
  auto centre_y = [](P a, P b, P c) {
    // Circumcentre y from |C-a| = |C-b| = |C-c| solved by the 2x2 system (independent of the code's form).
    const double a11 = 2 * (b[0] - a[0]), a12 = 2 * (b[1] - a[1]);
    const double a21 = 2 * (c[0] - a[0]), a22 = 2 * (c[1] - a[1]);
    const double r1 = b[0] * b[0] + b[1] * b[1] - a[0] * a[0] - a[1] * a[1];
    const double r2 = c[0] * c[0] + c[1] * c[1] - a[0] * a[0] - a[1] * a[1];
    return (a11 * r2 - a21 * r1) / (a11 * a22 - a12 * a21);
  };
  const double expected_y = (centre_y(pts[1], pts[2], pts[3]) + centre_y(pts[0], pts[2], pts[3]) +
                             centre_y(pts[0], pts[1], pts[3]) + centre_y(pts[0], pts[1], pts[2])) / 4.0;
  const auto c = circle_through_points(pts);
  ASSERT_TRUE(c.has_value());
  EXPECT_NEAR(c->centre_x, 0.0, 1e-12);  // symmetric about the y axis
  EXPECT_NEAR(c->centre_y, expected_y, 1e-12);
  double r = 0;
  for (const P& p : pts) r += std::hypot(p[0] - c->centre_x, p[1] - expected_y);
  EXPECT_NEAR(c->radius, r / 4.0, 1e-12);
}

TEST(CircleData, CollinearOrRepeatedPointsGiveNoCircle) {
  const std::array<P, 3> line{P{0, 0}, P{1, 1}, P{2, 2}};
  EXPECT_FALSE(circle_through_points(line).has_value());
  const std::array<P, 3> repeated{P{1, 1}, P{1, 1}, P{3, 0}};
  EXPECT_FALSE(circle_through_points(repeated).has_value());
  const std::array<P, 2> two{P{0, 0}, P{1, 0}};
  EXPECT_FALSE(circle_through_points(two).has_value());
}

}  // namespace
}  // namespace drycut::parser
