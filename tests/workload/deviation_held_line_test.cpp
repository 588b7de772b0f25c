// Held-line crossings of control points (EXPERIMENT.md §7, the microscope) against hand-computed
// geometry: straight lines, circles and their tool envelopes, crossings solved by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "workload/deviation_held_line.hpp"

namespace drycut::workload {
namespace {

constexpr double kPi = std::numbers::pi;

PolylineIndex indexed(const std::vector<Vec2>& points, bool closed = false) {
  PolylineIndex index;
  index.add_polyline(points, closed);
  index.build();
  return index;
}

std::vector<Vec2> circle(const Vec2& centre, double radius, int n = 7200) {
  std::vector<Vec2> points;
  for (int k = 0; k < n; ++k)
    points.push_back(centre + radius * Vec2(std::cos(2 * kPi * k / n), std::sin(2 * kPi * k / n)));
  return points;
}

// A straight line through (x0, 0) in direction (0.8, 0.6), from s = -12 to s = +12.
std::vector<Vec2> sloped_line(double x0) { return {Vec2(x0 - 9.6, -7.2), Vec2(x0 + 9.6, 7.2)}; }

TEST(PolylineIndexCrossings, FractionsAlongTheQuerySegment) {
  // A zigzag crossing y = 0 at x = 1, 3, 5 (between its vertices at y = +-1).
  const PolylineIndex zigzag = indexed({Vec2(0, -1), Vec2(2, 1), Vec2(4, -1), Vec2(6, 1)});
  const auto t = zigzag.crossings(Vec2(0, 0), Vec2(10, 0));
  ASSERT_EQ(t.size(), 3u);
  EXPECT_NEAR(t[0], 0.1, 1e-12);
  EXPECT_NEAR(t[1], 0.3, 1e-12);
  EXPECT_NEAR(t[2], 0.5, 1e-12);
  EXPECT_TRUE(zigzag.crossings(Vec2(0, 2), Vec2(10, 2)).empty());  // above everything
  EXPECT_TRUE(zigzag.crossings(Vec2(1.5, 0), Vec2(2.5, 0)).empty());  // ends between crossings
  EXPECT_TRUE(PolylineIndex{}.crossings(Vec2(0, 0), Vec2(1, 0)).empty());
}

TEST(HeldLineCrossing, FollowsTheLineWhereTheNearestPointAnswerIsOff) {
  // The contour x = 2.5 + (4/3) y crosses the held line y = 0 at x = 2.5; its normal distance
  // from the point (0, 0) is 2.5 * 0.6 = 1.5 mm, 1 mm less than the microscope reads.
  const PolylineIndex contour = indexed(sloped_line(2.5));
  const ControlPoint point{Vec2(0, 0), false};
  ASSERT_NEAR(contour.nearest(point.nominal).distance, 1.5, 1e-12);
  const auto d = held_line_polyline_crossing(contour, point, 3.0);
  ASSERT_TRUE(d);
  EXPECT_NEAR(*d, 2.5, 1e-12);
  EXPECT_FALSE(held_line_polyline_crossing(contour, point, 2.0));  // beyond the range: none
  // Held X: the line x = 0 meets the same contour at y = -2.5 * 0.75 = -1.875.
  const auto dy = held_line_polyline_crossing(contour, {Vec2(0, 0), true}, 3.0);
  ASSERT_TRUE(dy);
  EXPECT_NEAR(*dy, -1.875, 1e-12);
}

TEST(HeldLineCrossing, TheClosestOfTwoCrossingsWins) {
  // Circle of radius 3 about (0, 4): the line y = 2 meets it at x = +-sqrt(5); from x = 0.5 the
  // nearer one is +sqrt(5) - 0.5, the other -sqrt(5) - 0.5.
  const PolylineIndex contour = indexed(circle(Vec2(0, 4), 3.0), true);
  const auto d = held_line_polyline_crossing(contour, {Vec2(0.5, 2), false}, 5.0);
  ASSERT_TRUE(d);
  EXPECT_NEAR(*d, std::sqrt(5.0) - 0.5, 1e-5);
  const auto left = held_line_polyline_crossing(contour, {Vec2(-0.5, 2), false}, 5.0);
  ASSERT_TRUE(left);
  EXPECT_NEAR(*left, -std::sqrt(5.0) + 0.5, 1e-5);
  // Held X at x = 1: y = 4 +- sqrt(8), from y = 0.5 the lower one.
  const auto dy = held_line_polyline_crossing(contour, {Vec2(1, 0.5), true}, 5.0);
  ASSERT_TRUE(dy);
  EXPECT_NEAR(*dy, 4 - std::sqrt(8.0) - 0.5, 1e-5);
}

TEST(HeldLineCrossing, NoCrossingIsNoAnswer) {
  // The line y = 0 passes below the circle of radius 3 about (0, 4) whatever the range.
  const PolylineIndex contour = indexed(circle(Vec2(0, 4), 3.0), true);
  EXPECT_FALSE(held_line_polyline_crossing(contour, {Vec2(0.5, 0), false}, 50.0));
}

TEST(HeldLineCutCrossing, TheCutEdgeOfAStraightToolPath) {
  // Tool-centre line through (4.5, 0) along (0.8, 0.6), R = 1.2: its envelope is the two lines at
  // normal distance 1.2, which y = 0 meets at x = 4.5 -+ 1.2 / 0.6 = 2.5 and 6.5. The part lies on
  // the side of the programmed contour, the line through (2.5, 0).
  const PolylineIndex tool = indexed(sloped_line(4.5));
  const PolylineIndex programmed = indexed(sloped_line(2.5));
  const auto d = held_line_cut_crossing(tool, 1.2, programmed, {Vec2(0, 0), false}, 5.0);
  ASSERT_TRUE(d);
  EXPECT_NEAR(*d, 2.5, 1e-6);
  EXPECT_FALSE(held_line_cut_crossing(tool, 1.2, programmed, {Vec2(0, 0), false}, 2.4));
  // From x = 9 the far edge (x = 6.5, 4 mm from the programmed contour) is nearer; it is air,
  // not the part, so the answer is the part's edge 6.5 mm back.
  const auto far = held_line_cut_crossing(tool, 1.2, programmed, {Vec2(9, 0), false}, 8.0);
  ASSERT_TRUE(far);
  EXPECT_NEAR(*far, -6.5, 1e-6);
}

TEST(HeldLineCutCrossing, ClosestCrossingOfACircularCutAndNoneBesideIt) {
  // Programmed circle r = 3 about (0, 4), the tool (R = 2) outside it: tool centre on r = 5, the
  // part's edge r = 3, the far edge r = 7.
  const PolylineIndex programmed = indexed(circle(Vec2(0, 4), 3.0), true);
  const PolylineIndex tool = indexed(circle(Vec2(0, 4), 5.0), true);
  const auto d = held_line_cut_crossing(tool, 2.0, programmed, {Vec2(0.5, 2), false}, 5.0);
  ASSERT_TRUE(d);
  EXPECT_NEAR(*d, std::sqrt(5.0) - 0.5, 1e-5);  // y = 2 meets r = 3 at x = +-sqrt(5)
  // y = 0 misses the part (r = 3) and meets only the far edge at x = +-sqrt(33) = +-5.745.
  EXPECT_FALSE(held_line_cut_crossing(tool, 2.0, programmed, {Vec2(0.5, 0), false}, 8.0));
  EXPECT_FALSE(held_line_cut_crossing(PolylineIndex{}, 2.0, programmed, {Vec2(0.5, 2), false}, 5.0));
}

TEST(ControlPointMae, CountsThePointsWithoutCrossing) {
  const ControlPointMae m = control_point_mae({0.1, std::nullopt, -0.3, std::nullopt});
  EXPECT_EQ(m.points, 4u);
  EXPECT_EQ(m.measured, 2u);
  EXPECT_EQ(m.without_crossing, 2u);
  ASSERT_TRUE(m.mae_mm);
  EXPECT_NEAR(*m.mae_mm, 0.2, 1e-15);
  EXPECT_FALSE(control_point_mae({std::nullopt}).mae_mm);
}

}  // namespace
}  // namespace drycut::workload
