#include "interp/geometry/arc_solvers.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "interp/geometry/arc_curve.hpp"
#include "interp/geometry/line_curve.hpp"

namespace drycut::geometry {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;

const ArcCurve& as_arc(const ArcResult& r) {
  const auto* arc = dynamic_cast<const ArcCurve*>(r.curve.get());
  if (!arc) throw std::runtime_error("not an arc: alarm " + std::to_string(r.alarm) + " " + r.detail);
  return *arc;
}

void expect_point(const Vec3& a, const Vec3& b, double tol = 1e-9) {
  EXPECT_LT((a - b).norm(), tol) << a.transpose() << " vs " << b.transpose();
}

TEST(ArcFromCenter, G3AndG2QuarterAndThreeQuarterInG17) {
  const ArcResult ccw = arc_from_center({10, 0, 0}, {0, 10, 0}, {0, 0, 0}, false, Plane::G17, 0, {});
  ASSERT_TRUE(ccw.ok()) << ccw.detail;
  EXPECT_NEAR(ccw.curve->length(), 5 * kPi, 1e-12);
  expect_point(ccw.curve->at(ccw.curve->length() / 2).position, {10 * std::cos(45 * kDeg), 10 * std::sin(45 * kDeg), 0});
  const ArcResult cw = arc_from_center({10, 0, 0}, {0, 10, 0}, {0, 0, 0}, true, Plane::G17, 0, {});
  ASSERT_TRUE(cw.ok());
  EXPECT_NEAR(cw.curve->length(), 15 * kPi, 1e-12);
  expect_point(cw.curve->at(cw.curve->length() / 3).position, {0, -10, 0});  // through -90 deg
  expect_point(cw.curve->end(), {0, 10, 0});
}

TEST(ArcFromCenter, G18AndG19Orientation) {
  // G18: looking from +Y, G3 turns Z towards X.
  const ArcResult g18 = arc_from_center({0, 0, 10}, {10, 0, 0}, {0, 0, 0}, false, Plane::G18, 0, {});
  ASSERT_TRUE(g18.ok());
  EXPECT_NEAR(g18.curve->length(), 5 * kPi, 1e-12);
  expect_point(g18.curve->at(2.5 * kPi).position, {10 / std::sqrt(2.0), 0, 10 / std::sqrt(2.0)});
  const ArcResult g18cw = arc_from_center({0, 0, 10}, {10, 0, 0}, {0, 0, 0}, true, Plane::G18, 0, {});
  EXPECT_NEAR(g18cw.curve->length(), 15 * kPi, 1e-12);
  // G19: looking from +X, G3 turns Y towards Z.
  const ArcResult g19 = arc_from_center({0, 10, 0}, {0, 0, 10}, {0, 0, 0}, false, Plane::G19, 0, {});
  ASSERT_TRUE(g19.ok());
  EXPECT_NEAR(g19.curve->length(), 5 * kPi, 1e-12);
}

TEST(ArcFromCenter, FullCircleAndTurnsAndHelix) {
  const ArcResult full = arc_from_center({10, 0, 0}, {10, 0, 0}, {0, 0, 0}, false, Plane::G17, 0, {});
  ASSERT_TRUE(full.ok());
  EXPECT_NEAR(full.curve->length(), 20 * kPi, 1e-12);
  // Full circle plus TURN=1 with 5 mm rise: sweep 4 pi.
  const ArcResult helix = arc_from_center({10, 0, 0}, {10, 0, 5}, {0, 0, 0}, false, Plane::G17, 1, {});
  ASSERT_TRUE(helix.ok());
  EXPECT_NEAR(helix.curve->length(), std::hypot(40 * kPi, 5.0), 1e-12);
  expect_point(helix.curve->end(), {10, 0, 5});
  expect_point(helix.curve->at(helix.curve->length() / 2).position, {10, 0, 2.5});
  // Quarter plus TURN=2 clockwise.
  const ArcResult turns = arc_from_center({10, 0, 0}, {0, -10, 3}, {0, 0, 0}, true, Plane::G17, 2, {});
  ASSERT_TRUE(turns.ok());
  EXPECT_NEAR(as_arc(turns).sweep(), -(kPi / 2 + 4 * kPi), 1e-12);
  EXPECT_NEAR(turns.curve->length(), std::hypot(10 * (4.5 * kPi), 3.0), 1e-12);
}

TEST(ArcFromCenter, NegativeTurnIs14048) {
  const ArcResult r = arc_from_center({10, 0, 0}, {0, 10, 0}, {0, 0, 0}, false, Plane::G17, -1, {});
  EXPECT_EQ(r.alarm, 14048);
  EXPECT_EQ(r.curve, nullptr);
}

TEST(ArcFromCenter, RadiusDifferenceWithinToleranceIsCorrected) {
  // r_start = 10, r_end = 10.008: inside max(0.01, 10 * 0.001) = 0.01.
  const Vec3 end(0, 10.008, 0);
  const ArcResult r = arc_from_center({10, 0, 0}, end, {0, 0, 0}, false, Plane::G17, 0, {});
  ASSERT_TRUE(r.ok()) << r.detail;
  expect_point(r.curve->start(), {10, 0, 0});
  expect_point(r.curve->end(), end);
  // The corrected centre lies on the perpendicular bisector of the chord.
  const Vec3 c = as_arc(r).centre();
  EXPECT_NEAR((c - Vec3(10, 0, 0)).norm(), (c - end).norm(), 1e-9);
  EXPECT_LT(c.norm(), 0.01);
}

TEST(ArcFromCenter, RadiusDifferenceOutsideToleranceIs14040WithBothRadii) {
  const ArcResult r = arc_from_center({10, 0, 0}, {0, 10.02, 0}, {0, 0, 0}, false, Plane::G17, 0, {});
  EXPECT_EQ(r.alarm, 14040);
  EXPECT_NE(r.detail.find("10.000000"), std::string::npos) << r.detail;
  EXPECT_NE(r.detail.find("10.020000"), std::string::npos) << r.detail;
  // The factor term governs large radii: r = 100 allows 0.1.
  EXPECT_TRUE(arc_from_center({100, 0, 0}, {0, 100.09, 0}, {0, 0, 0}, false, Plane::G17, 0, {}).ok());
  EXPECT_EQ(arc_from_center({100, 0, 0}, {0, 100.11, 0}, {0, 0, 0}, false, Plane::G17, 0, {}).alarm, 14040);
  // A profile may widen the tolerance.
  ArcTolerance wide;
  wide.error_const_mm = 0.05;
  EXPECT_TRUE(arc_from_center({10, 0, 0}, {0, 10.02, 0}, {0, 0, 0}, false, Plane::G17, 0, wide).ok());
}

TEST(ArcFromCenter, CentreOnStartIs14040) {
  EXPECT_EQ(arc_from_center({1, 1, 0}, {2, 2, 0}, {1, 1, 0}, false, Plane::G17, 0, {}).alarm, 14040);
}

TEST(ArcFromRadius, PlusAndMinusRadius) {
  const ArcResult minor = arc_from_radius({10, 0, 0}, {0, 10, 0}, 10.0, false, Plane::G17);
  ASSERT_TRUE(minor.ok());
  EXPECT_NEAR(minor.curve->length(), 5 * kPi, 1e-9);
  expect_point(as_arc(minor).centre(), {0, 0, 0});
  const ArcResult major = arc_from_radius({10, 0, 0}, {0, 10, 0}, -10.0, false, Plane::G17);
  ASSERT_TRUE(major.ok());
  EXPECT_NEAR(major.curve->length(), 15 * kPi, 1e-9);
  expect_point(as_arc(major).centre(), {10, 10, 0});
  // G2 minor arc from (10,0) to (0,10): centre (10,10), passing (10-5v2, 10-5v2).
  const ArcResult cw = arc_from_radius({10, 0, 0}, {0, 10, 0}, 10.0, true, Plane::G17);
  ASSERT_TRUE(cw.ok());
  expect_point(as_arc(cw).centre(), {10, 10, 0});
  const double d = 10 - 10 / std::sqrt(2.0);
  expect_point(cw.curve->at(cw.curve->length() / 2).position, {d, d, 0});
  EXPECT_NEAR(cw.curve->length(), 5 * kPi, 1e-9);
}

TEST(ArcFromRadius, HalfCircleAndHelix) {
  const ArcResult half = arc_from_radius({-5, 0, 0}, {5, 0, 4}, 5.0, true, Plane::G17);
  ASSERT_TRUE(half.ok());
  EXPECT_NEAR(half.curve->length(), std::hypot(5 * kPi, 4.0), 1e-9);
  expect_point(half.curve->at(half.curve->length() / 2).position, {0, 5, 2});  // CW from -X passes +Y
}

TEST(ArcFromRadius, Alarms) {
  EXPECT_EQ(arc_from_radius({1, 0, 0}, {1, 0, 0}, 5.0, false, Plane::G17).alarm, 14040);  // full circle
  EXPECT_EQ(arc_from_radius({0, 0, 0}, {1, 0, 0}, 0.0, false, Plane::G17).alarm, 14040);
  EXPECT_EQ(arc_from_radius({0, 0, 0}, {30, 0, 0}, 10.0, false, Plane::G17).alarm, 14040);  // too small
  // Chord longer than the diameter by less than the tolerance: a half circle.
  EXPECT_TRUE(arc_from_radius({0, 0, 0}, {20.005, 0, 0}, 10.0, false, Plane::G17).ok());
}

TEST(ArcFromAngle, WithCentre) {
  const ArcResult r = arc_from_angle_and_center({10, 0, 2}, {10, 0, 2}, {0, 0, 0}, 90 * kDeg, false, Plane::G17);
  ASSERT_TRUE(r.ok());
  expect_point(r.curve->end(), {0, 10, 2});
  const ArcResult cw = arc_from_angle_and_center({10, 0, 0}, {10, 0, 0}, {0, 0, 0}, 30 * kDeg, true, Plane::G17);
  expect_point(cw.curve->end(), {10 * std::cos(30 * kDeg), -10 * std::sin(30 * kDeg), 0});
  EXPECT_EQ(arc_from_angle_and_center({10, 0, 0}, {10, 0, 0}, {0, 0, 0}, 0.0, true, Plane::G17).alarm, 12160);
  EXPECT_EQ(arc_from_angle_and_center({10, 0, 0}, {10, 0, 0}, {0, 0, 0}, 7.0, true, Plane::G17).alarm, 12160);
}

// Fundamentals, "Helical interpolation (G2/G3, TURN)": the AR= and CR= forms take the normal
// axis and TURN= as the centre form does. By hand: radius 10, quarter turn, Z -5:
// length sqrt((10 pi / 2)^2 + 5^2) = 16.4845; with TURN=1 the sweep is 450 deg:
// sqrt((10 * 2.5 pi)^2 + 5^2) = 78.6988 and the end is the same point.
TEST(ArcFromAngle, HelixAndTurns) {
  const ArcResult q = arc_from_angle_and_center({10, 0, 0}, {10, 0, -5}, {0, 0, 0}, 90 * kDeg, false, Plane::G17);
  ASSERT_TRUE(q.ok());
  expect_point(q.curve->end(), {0, 10, -5});
  EXPECT_NEAR(q.curve->length(), 16.4845, 1e-4);
  const ArcResult t = arc_from_angle_and_center({10, 0, 0}, {10, 0, -5}, {0, 0, 0}, 90 * kDeg, false, Plane::G17, 1);
  ASSERT_TRUE(t.ok());
  expect_point(t.curve->end(), {0, 10, -5});
  EXPECT_NEAR(t.curve->length(), 78.6988, 1e-4);
  const ArcResult e = arc_from_angle_and_end({10, 0, 0}, {0, 10, -5}, 90 * kDeg, false, Plane::G17, 1);
  ASSERT_TRUE(e.ok());
  expect_point(e.curve->end(), {0, 10, -5});
  EXPECT_NEAR(e.curve->length(), 78.6988, 1e-4);
  // CR=10 half circle with TURN=1: 540 deg, sqrt((10 * 3 pi)^2 + 4^2) = 94.3326.
  const ArcResult c = arc_from_radius({10, 0, 0}, {-10, 0, -4}, 10.0, true, Plane::G17, {}, 1);
  ASSERT_TRUE(c.ok());
  expect_point(c.curve->end(), {-10, 0, -4});
  EXPECT_NEAR(c.curve->length(), 94.3326, 1e-4);
}

TEST(ArcFromAngle, WithEndPoint) {
  const ArcResult q = arc_from_angle_and_end({10, 0, 0}, {0, 10, 0}, 90 * kDeg, false, Plane::G17);
  ASSERT_TRUE(q.ok());
  expect_point(as_arc(q).centre(), {0, 0, 0});
  EXPECT_NEAR(as_arc(q).radius(), 10, 1e-9);
  const ArcResult big = arc_from_angle_and_end({10, 0, 0}, {0, 10, 0}, 270 * kDeg, false, Plane::G17);
  ASSERT_TRUE(big.ok());
  expect_point(as_arc(big).centre(), {10, 10, 0});
  EXPECT_NEAR(big.curve->length(), 15 * kPi, 1e-9);
  expect_point(big.curve->end(), {0, 10, 0});
  const ArcResult cw = arc_from_angle_and_end({10, 0, 0}, {0, 10, 0}, 90 * kDeg, true, Plane::G17);
  expect_point(as_arc(cw).centre(), {10, 10, 0});
  EXPECT_EQ(arc_from_angle_and_end({1, 0, 0}, {1, 0, 0}, 1.0, true, Plane::G17).alarm, 14040);
}

TEST(ArcThroughPoint, ThreePointsOnATiltedCircle) {
  // Circle centre (1,2,3), radius 5, in the plane spanned by e1 and e2 (tilted 30 deg about X).
  const Vec3 c(1, 2, 3), e1(1, 0, 0), e2(0, std::cos(30 * kDeg), std::sin(30 * kDeg));
  auto on = [&](double deg) { return Vec3(c + 5 * (std::cos(deg * kDeg) * e1 + std::sin(deg * kDeg) * e2)); };
  const ArcResult r = arc_through_point(on(0), on(100), on(200));
  ASSERT_TRUE(r.ok()) << r.detail;
  EXPECT_NEAR(r.curve->length(), 5 * 200 * kDeg, 1e-9);
  expect_point(as_arc(r).centre(), c);
  expect_point(r.curve->at(5 * 100 * kDeg).position, on(100));
  expect_point(r.curve->at(5 * 50 * kDeg).position, on(50));
  expect_point(r.curve->end(), on(200));
  // The same circle traversed the other way round (intermediate at -100 deg) is 160 deg long.
  const ArcResult back = arc_through_point(on(0), on(-100), on(200));
  EXPECT_NEAR(back.curve->length(), 5 * 160 * kDeg, 1e-9);
  expect_point(back.curve->at(5 * 100 * kDeg).position, on(-100));
}

TEST(ArcThroughPoint, CollinearOrCoincidentIs14040) {
  EXPECT_EQ(arc_through_point({0, 0, 0}, {1, 1, 1}, {2, 2, 2}).alarm, 14040);
  EXPECT_EQ(arc_through_point({0, 0, 0}, {0, 0, 0}, {2, 2, 2}).alarm, 14040);
}

TEST(ArcTangent, ContinuesTheGivenDirection) {
  // Leaving (0,0) along +X to (10,10): the quarter circle around (0,10), counter-clockwise.
  const ArcResult r = arc_tangent({0, 0, 0}, {1, 0, 0}, {10, 10, 0}, Plane::G17);
  ASSERT_TRUE(r.ok()) << r.detail;
  expect_point(as_arc(r).centre(), {0, 10, 0});
  EXPECT_NEAR(r.curve->length(), 5 * kPi, 1e-9);
  expect_point(r.curve->at(0).tangent, {1, 0, 0}, 1e-12);
  // Ending below the tangent turns clockwise; tangent still continuous.
  const ArcResult cw = arc_tangent({0, 0, 0}, {1, 1, 0}, {4, 0, 0}, Plane::G17);
  ASSERT_TRUE(cw.ok());
  expect_point(cw.curve->at(0).tangent, Vec3(1, 1, 0).normalized(), 1e-12);
  expect_point(cw.curve->end(), {4, 0, 0});
  expect_point(as_arc(cw).centre(), {2, -2, 0});
}

TEST(ArcTangent, StraightAheadIsALineAndBehindIs14040) {
  const ArcResult ahead = arc_tangent({0, 0, 0}, {1, 0, 0}, {5, 0, 0}, Plane::G17);
  ASSERT_TRUE(ahead.ok());
  EXPECT_NE(dynamic_cast<const LineCurve*>(ahead.curve.get()), nullptr);
  EXPECT_NEAR(ahead.curve->length(), 5, 1e-12);
  EXPECT_EQ(arc_tangent({0, 0, 0}, {1, 0, 0}, {-5, 0, 0}, Plane::G17).alarm, 14040);
  EXPECT_EQ(arc_tangent({0, 0, 0}, {0, 0, 1}, {5, 5, 0}, Plane::G17).alarm, 14040);
}

TEST(ArcSolvers, NonFiniteInputIsAnAlarmNotACrash) {
  const double nan = std::nan("");
  EXPECT_NE(arc_from_center({nan, 0, 0}, {0, 1, 0}, {0, 0, 0}, false, Plane::G17, 0, {}).alarm, 0);
  EXPECT_NE(arc_from_radius({0, 0, 0}, {0, 1, 0}, nan, false, Plane::G17).alarm, 0);
  EXPECT_NE(arc_through_point({0, 0, 0}, {0, 1, 0}, {nan, 0, 0}).alarm, 0);
}

}  // namespace
}  // namespace drycut::geometry
