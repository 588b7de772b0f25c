// Polar coordinates: poles G110/G111/G112, AP=/RP= with G0/G1/G2/G3, AP=IC. Expected positions
// are computed by hand in the comments.
#include <cmath>
#include <numbers>

#include "interp_test_support.hpp"

namespace drycut::interp::testing {
namespace {

using Eigen::Vector3d;

Vector3d end_of(const RunResult& r, size_t motion) { return r.sink.motions().at(motion).curve->end(); }

TEST(PolarCoordinates, PoleBlockDoesNotMoveAndNeedsNoFeed) {
  // G111 X10 Y10 only defines the pole; G1 AP=90 RP=5 goes to (10, 10 + 5) = (10, 15).
  auto r = run_program("G0 X0 Y0 Z0\nG111 X10 Y10\nG1 AP=90 RP=5 F100\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  ASSERT_EQ(r->sink.motions().size(), 2u);
  EXPECT_TRUE(near(end_of(*r, 1), Vector3d(10, 15, 0)));
}

TEST(PolarCoordinates, WithoutAPoleTheWorkpieceZeroIsThePole) {
  // AP=30 RP=10: (10 cos 30, 10 sin 30) = (8.6603, 5); under G54 = (10, 20): (18.6603, 25).
  auto r = run_program("G0 X0 Y0 Z0\nG0 AP=30 RP=10\nG54 G0 AP=30 RP=10\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  EXPECT_TRUE(near(end_of(*r, 1), Vector3d(10 * std::sqrt(3.0) / 2, 5, 0)));
  EXPECT_TRUE(near(end_of(*r, 2), Vector3d(10 + 10 * std::sqrt(3.0) / 2, 25, 0)));
}

TEST(PolarCoordinates, AngleAndRadiusAreKeptAndApIcAdds) {
  // Pole (10, 10): AP=0 RP=5 -> (15, 10); AP=IC(90) -> 90 deg -> (10, 15); RP=2 keeps 90 -> (10, 12).
  auto r = run_program("G0 X0 Y0 Z0\nG111 X10 Y10\nG0 AP=0 RP=5\nAP=IC(90)\nRP=2\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  EXPECT_TRUE(near(end_of(*r, 1), Vector3d(15, 10, 0)));
  EXPECT_TRUE(near(end_of(*r, 2), Vector3d(10, 15, 0)));
  EXPECT_TRUE(near(end_of(*r, 3), Vector3d(10, 12, 0)));
}

TEST(PolarCoordinates, G110RelativeToPositionAndG112RelativeToPole) {
  // At (20, 0): G110 X5 Y5 -> pole (25, 5); AP=180 RP=10 -> (15, 5).
  // G112 X-5 -> pole (20, 5); AP=90 RP=2 -> (20, 7).
  // G112 AP=0 RP=10 -> pole (30, 5) (polar form about the last pole); AP=270 RP=1 -> (30, 4).
  auto r = run_program(
      "G0 X20 Y0 Z0\nG110 X5 Y5\nG0 AP=180 RP=10\nG112 X-5\nG0 AP=90 RP=2\nG112 AP=0 RP=10\nG0 AP=270 RP=1\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  EXPECT_TRUE(near(end_of(*r, 1), Vector3d(15, 5, 0)));
  EXPECT_TRUE(near(end_of(*r, 2), Vector3d(20, 7, 0)));
  EXPECT_TRUE(near(end_of(*r, 3), Vector3d(30, 4, 0)));
}

TEST(PolarCoordinates, CircleAboutThePole) {
  // From (15, 10), pole (10, 10): G3 AP=180 RP=5 is the upper half circle to (5, 10) through (10, 15);
  // G2 AP=90 is the quarter from 180 back clockwise to 90 deg: (10, 15) through 10 + 5(c135, s135).
  auto r = run_program("G0 X15 Y10 Z0\nG111 X10 Y10\nG3 AP=180 RP=5 F100\nG2 AP=90\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  auto m = r->sink.motions();
  ASSERT_EQ(m.size(), 3u);
  EXPECT_TRUE(near(m[1].curve->at(m[1].curve->length() / 2).position, Vector3d(10, 15, 0)));
  EXPECT_TRUE(near(m[1].curve->end(), Vector3d(5, 10, 0)));
  EXPECT_NEAR(m[1].curve->length(), 5 * std::numbers::pi, 1e-9);
  const double h = 5 / std::sqrt(2.0);
  EXPECT_TRUE(near(m[2].curve->at(m[2].curve->length() / 2).position, Vector3d(10 - h, 10 + h, 0)));
  EXPECT_TRUE(near(m[2].curve->end(), Vector3d(10, 15, 0)));
}

TEST(PolarCoordinates, CylinderCoordinatesAndOtherPlanes) {
  // G17: AP=45 RP=10 Z-5 -> (7.0711, 7.0711, -5).
  // G18 (first axis Z, second X): pole Z0 X0, AP=90 RP=10 -> X10 Z0, Y as programmed (3).
  // G19 (first axis Y, second Z): AP=0 RP=4 -> Y4 Z0 (the pole is still Z0 X0 -> Y0 Z0 in G19).
  auto r = run_program(
      "G0 X0 Y0 Z0\nG111 X0 Y0\nG1 AP=45 RP=10 Z-5 F100\nG18 G111 Z0 X0\nG0 AP=90 RP=10 Y3\nG19 G0 AP=0 RP=4\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  const double h = 10 / std::sqrt(2.0);
  EXPECT_TRUE(near(end_of(*r, 1), Vector3d(h, h, -5)));
  EXPECT_TRUE(near(end_of(*r, 2), Vector3d(10, 3, 0)));
  EXPECT_TRUE(near(end_of(*r, 3), Vector3d(10, 4, 0)));
}

TEST(PolarCoordinates, PolarPointsGoThroughTheFrame) {
  // TRANS X100, pole at the workpiece zero: AP=0 RP=10 -> (110, 0); AROT RPL=90 -> (100, 10).
  auto r = run_program("G0 X0 Y0 Z0\nTRANS X100\nG111 X0 Y0\nG0 AP=0 RP=10\nAROT RPL=90\nG0 AP=0 RP=10\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  EXPECT_TRUE(near(end_of(*r, 1), Vector3d(110, 0, 0)));
  EXPECT_TRUE(near(end_of(*r, 2), Vector3d(100, 10, 0)));
}

TEST(PolarCoordinates, InchRadius) {
  // G70: RP=1 is 25.4 mm.
  auto r = run_program("G0 X0 Y0 Z0\nG70 G0 AP=90 RP=1\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  EXPECT_TRUE(near(end_of(*r, 1), Vector3d(0, 25.4, 0)));
}

}  // namespace
}  // namespace drycut::interp::testing
