// Tool lengths 1..3 with their wear and base lengths on the axes by tool type and plane, and the
// reference point of a turning tool under G41/G42 (cutting edge position). Function Manual W1,
// "Tool length compensation"; docs/controller-state.md "Tools and offsets". Every expected value
// is worked out in the comments.
#include "interp_test_support.hpp"

namespace drycut::interp::testing {
namespace {

using Eigen::Vector3d;

// The carrier position of the first motion's end (G54 of the test profile: X10 Y20 Z0).
Vector3d end_of_first_move(const std::string& program) {
  auto r = run_program(program);
  EXPECT_FALSE(r->alarm) << r->alarm->format();
  const auto motions = r->sink.motions();
  return motions.empty() ? Vector3d::Constant(1e9) : Vector3d(motions.front().curve->end());
}

const char* kMillingLengths =
    "$TC_DP1[1,1]=120 $TC_DP3[1,1]=100 $TC_DP4[1,1]=20 $TC_DP5[1,1]=3\n"
    "$TC_DP12[1,1]=0.5 $TC_DP13[1,1]=-0.1 $TC_DP14[1,1]=0.2\n"
    "$TC_DP21[1,1]=10 $TC_DP22[1,1]=1 $TC_DP23[1,1]=2\n";

TEST(ToolLengths, MillingToolLengthsByPlane) {
  // L1 = 100 + 0.5 + 10 = 110.5, L2 = 20 - 0.1 + 1 = 20.9, L3 = 3 + 0.2 + 2 = 5.2.
  // G17: L1 on Z, L2 on Y, L3 on X; G18: L1 on Y, L2 on X, L3 on Z; G19: L1 on X, L2 on Z, L3 on Y.
  const std::string tail = " T1 M6 D1\nG0 G500 X0 Y0 Z0\nM30\n";
  EXPECT_TRUE(near(end_of_first_move(std::string(kMillingLengths) + "G17" + tail), Vector3d(5.2, 20.9, 110.5)));
  EXPECT_TRUE(near(end_of_first_move(std::string(kMillingLengths) + "G18" + tail), Vector3d(20.9, 110.5, 5.2)));
  EXPECT_TRUE(near(end_of_first_move(std::string(kMillingLengths) + "G19" + tail), Vector3d(110.5, 5.2, 20.9)));
}

TEST(ToolLengths, TurningToolLengthsWithWearAndLength3) {
  // Type 500 in G18: L1 (40 + 0.1) on X, L2 (60 - 0.2) on Z, L3 (5 + 0.3) on Y.
  const Vector3d end = end_of_first_move(
      "$TC_DP1[1,1]=500 $TC_DP3[1,1]=40 $TC_DP4[1,1]=60 $TC_DP5[1,1]=5\n"
      "$TC_DP12[1,1]=0.1 $TC_DP13[1,1]=-0.2 $TC_DP14[1,1]=0.3\n"
      "G18 T1 M6 D1\nG0 G500 X0 Y0 Z0\nM30\n");
  EXPECT_TRUE(near(end, Vector3d(40.1, 5.3, 59.8)));
}

TEST(ToolLengths, GeometryWrittenAfterWearKeepsTheWear) {
  // DP13 first, then DP4: length 2 = 60 + (-0.2); reading DP4 back gives the geometry part.
  auto r = run_program(
      "$TC_DP1[1,1]=500 $TC_DP13[1,1]=-0.2 $TC_DP4[1,1]=60\n"
      "R1=$TC_DP4[1,1] R2=$TC_DP13[1,1]\n"
      "IF (R1<>60) OR (R2<>-0.2) GOTOF BAD\nG18 T1 M6 D1\nG0 G500 Z0\nM30\nBAD: G0 X999\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  EXPECT_NEAR(r->sink.motions().front().curve->end()[2], 59.8, 1e-12);
}

// The compensation request of the first G41/G42 motion.
CompensationRequest first_compensated(const std::string& program) {
  auto r = run_program(program);
  EXPECT_FALSE(r->alarm) << r->alarm->format();
  for (const auto& m : r->sink.motions())
    if (m.compensation.side != CompensationSide::None) return m.compensation;
  ADD_FAILURE() << "no compensated motion";
  return {};
}

TEST(ToolLengths, EdgePositionGivesTheTipFromTheEdgeCentre) {
  // Edge position 3 in G18 (abscissa Z, ordinate X): P lies r behind S on both axes.
  const std::string tool = "$TC_DP1[1,1]=500 $TC_DP6[1,1]=0.8 $TC_DP2[1,1]=";
  const std::string moves = "\nT1 M6 D1\nG18 G42 G1 X20 Z2 F100\nZ-20\nM30\n";
  EXPECT_TRUE(near(first_compensated(tool + "3" + moves).reference_shift, Vector3d(-0.8, 0, -0.8)));
  // 5: P ahead of S on the abscissa only; 8: below it on the ordinate only.
  EXPECT_TRUE(near(first_compensated(tool + "5" + moves).reference_shift, Vector3d(0, 0, 0.8)));
  EXPECT_TRUE(near(first_compensated(tool + "8" + moves).reference_shift, Vector3d(-0.8, 0, 0)));
  // 9: S is the reference point.
  EXPECT_TRUE(near(first_compensated(tool + "9" + moves).reference_shift, Vector3d::Zero()));
  // G17 (abscissa X, ordinate Y), position 2: (-r, +r).
  const std::string g17 = "\nT1 M6 D1\nG17 G42 G1 X20 Y2 F100\nX-20\nM30\n";
  EXPECT_TRUE(near(first_compensated(tool + "2" + g17).reference_shift, Vector3d(-0.8, 0.8, 0)));
  // A milling tool has no edge position: its centre is the reference point.
  EXPECT_TRUE(near(first_compensated("$TC_DP1[1,1]=120 $TC_DP2[1,1]=3" + moves).reference_shift, Vector3d::Zero()));
}

}  // namespace
}  // namespace drycut::interp::testing
