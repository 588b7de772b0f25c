// Working planes G17/G18/G19 for circles: centre, AR=, CR=, CT, TURN=. Hand-computed positions;
// plane axes G17 (X, Y), G18 (Z, X), G19 (Y, Z), counter-clockwise (G3) seen from +normal.
#include <cmath>
#include <numbers>

#include "interp_test_support.hpp"

namespace drycut::interp::testing {
namespace {

using Eigen::Vector3d;
constexpr double kPi = std::numbers::pi;

Vector3d mid_of(const PathElement& e) { return e.curve->at(e.curve->length() / 2).position; }

TEST(Planes, AngleAndCentreEndWhereThePlaneTurns) {
  // G18: start X10 (Z0) is at 90 deg in (Z, X) about the centre (0, 0, 0); G3 AR=90 -> 180 deg:
  // Z = -10, X = 0. G2 AR=90 from X10 -> 0 deg: Z = 10.
  // G19: start Y10 at 0 deg in (Y, Z); G3 AR=90 -> 90 deg: Z = 10.
  auto r = run_program(
      "G0 X10 Y0 Z0\nG18 G3 I-10 K0 AR=90 F100\nG0 X10 Y0 Z0\nG2 I-10 K0 AR=90\n"
      "G0 X0 Y10 Z0\nG19 G3 J-10 K0 AR=90\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  auto m = r->sink.motions();
  ASSERT_EQ(m.size(), 6u);
  EXPECT_TRUE(near(m[1].curve->end(), Vector3d(0, 0, -10)));
  EXPECT_TRUE(near(m[3].curve->end(), Vector3d(0, 0, 10)));
  EXPECT_TRUE(near(m[5].curve->end(), Vector3d(0, 0, 10)));
}

TEST(Planes, RadiusCircleInG18TurnsClockwiseSeenFromPlusY) {
  // G18 G2 X20 Z0 CR=10 from the zero: centre (X10, Z0); the start is at -90 deg in (Z, X);
  // clockwise runs through -180 deg: midpoint Z = -10, X = 10. G3 back runs through Z = +10.
  auto r = run_program("G0 X0 Y0 Z0\nG18 G2 X20 Z0 CR=10 F100\nG3 X0 Z0 CR=10\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  auto m = r->sink.motions();
  EXPECT_TRUE(near(mid_of(m[1]), Vector3d(10, 0, -10)));
  EXPECT_TRUE(near(mid_of(m[2]), Vector3d(10, 0, -10)));  // G3 from X20 back to X0 is the same half
  EXPECT_NEAR(m[1].curve->length(), 10 * kPi, 1e-9);
}

TEST(Planes, TangentCircleInG19) {
  // G19: G1 to Y10 leaves along +Y; CT to Y20 Z10: the circle tangent to +Y at (10, 0) through
  // (20, 10) has r = 10 (100 + (10 - r)^2 = r^2), centre (Y10, Z10): a quarter, length 5 pi,
  // midpoint (Y 10 + 10 sin 45, Z 10 - 10 cos 45).
  auto r = run_program("G0 X0 Y0 Z0\nG19 G1 Y10 F100\nCT Y20 Z10\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  auto m = r->sink.motions();
  const double h = 10 / std::sqrt(2.0);
  EXPECT_NEAR(m[2].curve->length(), 5 * kPi, 1e-9);
  EXPECT_TRUE(near(mid_of(m[2]), Vector3d(0, 10 + h, 10 - h)));
}

TEST(Planes, TurnMakesAHelixAlongTheNormal) {
  // G18 from X10: G2 back to X10 Z0 with Y-20, I-10 K0 TURN=2: one full circle plus 2 turns = 6 pi
  // of radius 10 while Y runs 20 mm: length sqrt((60 pi)^2 + 20^2).
  auto r = run_program("G0 X10 Y0 Z0\nG18 G2 X10 Y-20 Z0 I-10 K0 TURN=2 F100\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  auto m = r->sink.motions();
  EXPECT_NEAR(m[1].curve->length(), std::hypot(60 * kPi, 20.0), 1e-6);
  EXPECT_TRUE(near(m[1].curve->end(), Vector3d(10, -20, 0)));
}

}  // namespace
}  // namespace drycut::interp::testing
