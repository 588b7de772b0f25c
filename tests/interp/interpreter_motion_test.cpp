// Lines, units, offsets, feeds, dwell, stops, tools: hand-computed expectations.
#include <cmath>
#include <numbers>

#include "interp_test_support.hpp"

namespace drycut::interp::testing {
namespace {

using Eigen::Vector3d;

TEST(Interpreter, LinesStartAtTheProfileStartAndFollowG90G91) {
  auto r = run_program("G1 X10 Y0 Z100 F1200\nG91 X5 Y5\nG90 Z=IC(-10)\nX=IC(1)\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  auto m = r->sink.motions();
  ASSERT_EQ(m.size(), 4u);
  EXPECT_TRUE(near(m[0].curve->start(), Vector3d(0, 0, 100)));
  EXPECT_TRUE(near(m[0].curve->end(), Vector3d(10, 0, 100)));
  EXPECT_TRUE(near(m[1].curve->end(), Vector3d(15, 5, 100)));
  EXPECT_TRUE(near(m[2].curve->end(), Vector3d(15, 5, 90)));
  EXPECT_TRUE(near(m[3].curve->end(), Vector3d(16, 5, 90)));
  EXPECT_DOUBLE_EQ(m[0].feed_mm_s, 20.0);  // F1200 mm/min
  EXPECT_EQ(m[0].label, "G1");
  EXPECT_TRUE(r->sink.finished);
}

TEST(Interpreter, RapidHasNoFeedAndG1NeedsOne) {
  auto ok = run_program("G0 X10\nM30\n");
  ASSERT_FALSE(ok->alarm);
  EXPECT_TRUE(ok->sink.motions()[0].rapid);
  auto bad = run_program("G1 X10\nM30\n");
  ASSERT_TRUE(bad->alarm);
  EXPECT_EQ(bad->alarm->number, 10860);
  EXPECT_EQ(bad->alarm->where.line, 1u);
}

TEST(Interpreter, InchAndMetricUnits) {
  // G70: positions in inch, feed still mm/min; G700 converts the feed too.
  auto r = run_program("G70 G1 X1 F60\nG700 X2 F60\nG71 X0\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  auto m = r->sink.motions();
  EXPECT_NEAR(m[0].curve->end().x(), 25.4, 1e-12);
  EXPECT_DOUBLE_EQ(m[0].feed_mm_s, 1.0);
  EXPECT_NEAR(m[1].curve->end().x(), 50.8, 1e-12);
  EXPECT_DOUBLE_EQ(m[1].feed_mm_s, 25.4);
  EXPECT_NEAR(m[2].curve->end().x(), 0.0, 1e-12);
}

TEST(Interpreter, WorkOffsetAndTranslationShiftMachinePositions) {
  auto r = run_program("G54 G0 X0 Y0\nTRANS X5\nG0 X0\nATRANS Y1\nG0 Y0\nTRANS\nG0 X0 Y0\nG53 G0 X0 Y0\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  auto m = r->sink.motions();
  ASSERT_EQ(m.size(), 5u);
  EXPECT_TRUE(near(m[0].curve->end(), Vector3d(10, 20, 100)));
  EXPECT_TRUE(near(m[1].curve->end(), Vector3d(15, 20, 100)));
  EXPECT_TRUE(near(m[2].curve->end(), Vector3d(15, 21, 100)));
  EXPECT_TRUE(near(m[3].curve->end(), Vector3d(10, 20, 100)));
  EXPECT_TRUE(near(m[4].curve->end(), Vector3d(0, 0, 100)));  // G53 suppresses the offsets
}

TEST(Interpreter, FeedPerRevolutionNeedsATurningSpindle) {
  auto r = run_program("G95 S1000 M3 G1 X10 F0.1\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  EXPECT_NEAR(r->sink.motions()[0].feed_mm_s, 0.1 * 1000 / 60.0, 1e-12);
  auto bad = run_program("G95 G1 X10 F0.1\nM30\n");
  ASSERT_TRUE(bad->alarm);
  EXPECT_EQ(bad->alarm->number, 10860);
}

TEST(Interpreter, DwellDoesNotChangeTheModalFeed) {
  auto r = run_program("G1 X1 F600\nG4 F2.5\nX2\nS1200 M3\nG4 S10\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  std::vector<PathElement> dwells;
  for (const auto& e : r->sink.elements)
    if (e.kind == ElementKind::Dwell) dwells.push_back(e);
  ASSERT_EQ(dwells.size(), 2u);
  EXPECT_DOUBLE_EQ(dwells[0].dwell_s, 2.5);
  EXPECT_DOUBLE_EQ(dwells[1].dwell_s, 0.5);  // 10 revolutions at 1200 rpm
  EXPECT_DOUBLE_EQ(r->sink.motions()[1].feed_mm_s, 10.0);
}

TEST(Interpreter, StopsToolChangeAndProgramEnd) {
  auto r = run_program("T=\"FR_4\"\nM6\nM0\nG1 X1 F100\nM30\nG1 X2\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  std::vector<ElementKind> kinds;
  for (const auto& e : r->sink.elements)
    if (e.kind != ElementKind::DynamicsChange) kinds.push_back(e.kind);
  ASSERT_EQ(kinds.size(), 4u);  // nothing after M30
  EXPECT_EQ(kinds[0], ElementKind::ToolChange);
  EXPECT_EQ(kinds[1], ElementKind::Stop);
  EXPECT_EQ(kinds[2], ElementKind::Line);
  EXPECT_EQ(kinds[3], ElementKind::Stop);
  EXPECT_EQ(r->sink.elements.back().stop, StopKind::ProgramEnd);
}

TEST(Interpreter, UnknownToolNameWarnsOrIsAnAlarmWithACompleteTable) {
  // Tool names are case-sensitive: "fr_4" is not FR_4.
  auto r = run_program("T=\"fr_4\"\nM6\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  ASSERT_EQ(r->diagnostics.items().size(), 1u);
  EXPECT_EQ(r->diagnostics.items()[0].number, 990012);
  auto profile = test_profile();
  profile.tool_table_complete = true;
  auto strict = run_program("T=\"fr_4\"\nM6\nM30\n", profile);
  ASSERT_TRUE(strict->alarm);
  EXPECT_EQ(strict->alarm->number, 17190);
  EXPECT_EQ(strict->alarm->where.line, 1u);
}

TEST(Interpreter, CompensationNeedsToolAndEdge) {
  auto none = run_program("G42 G1 X10 F100\nM30\n");
  ASSERT_TRUE(none->alarm);
  EXPECT_EQ(none->alarm->number, 10750);
  // D0 with a tool in the spindle selects no offset (W1): G41 runs with radius 0, no alarm.
  auto d0 = run_program("T=\"FR_4\"\nM6\nD0\nG41 G1 X10 F100\nM30\n");
  ASSERT_FALSE(d0->alarm) << d0->alarm->format();
  EXPECT_DOUBLE_EQ(d0->sink.motions()[0].compensation.radius_mm, 0.0);
  EXPECT_NEAR(d0->sink.motions()[0].curve->end().x(), 10.0, 1e-12);
  auto ok = run_program("T=\"FR_4\"\nM6\nG42 G1 X10 F100\nM30\n");
  ASSERT_FALSE(ok->alarm) << ok->alarm->format();
  const auto m = ok->sink.motions();
  EXPECT_EQ(m[0].compensation.side, CompensationSide::Right);
  EXPECT_DOUBLE_EQ(m[0].compensation.radius_mm, 2.0);
}

TEST(Interpreter, PlaneChangeWhileCompensatingIsAlarm10757) {
  auto r = run_program("T=\"FR_4\"\nM6\nG41 G1 X10 F100\nG18\nM30\n");
  ASSERT_TRUE(r->alarm);
  EXPECT_EQ(r->alarm->number, 10757);
  EXPECT_EQ(r->alarm->where.line, 4u);
}

TEST(Interpreter, SoftwareLimitSwitchIsAlarm10720) {
  auto r = run_program("G0 X999\nG0 X1001\nM30\n");
  ASSERT_TRUE(r->alarm);
  EXPECT_EQ(r->alarm->number, 10720);
  EXPECT_EQ(r->alarm->where.line, 2u);
}

TEST(Interpreter, DynamicsModesAreRecordedOnElements) {
  auto r = run_program("G64 SOFT G1 X1 F100\nG9 X2\nG60 BRISK X3\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  auto m = r->sink.motions();
  EXPECT_EQ(m[0].dynamics.transition, TransitionMode::Continuous);
  EXPECT_EQ(m[0].dynamics.profile, AccelProfile::Soft);
  EXPECT_FALSE(m[0].dynamics.exact_stop_this_block);
  EXPECT_TRUE(m[1].dynamics.exact_stop_this_block);
  EXPECT_EQ(m[2].dynamics.transition, TransitionMode::ExactStop);
  EXPECT_EQ(m[2].dynamics.profile, AccelProfile::Brisk);
}

TEST(Interpreter, ResetStateComesFromTheProfile) {
  auto profile = test_profile();
  profile.reset_gcodes = {"G0", "G64", "SOFT", "G91"};
  auto r = run_program("X5\nM30\n", profile);
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  auto m = r->sink.motions();
  EXPECT_TRUE(m[0].rapid);
  EXPECT_TRUE(near(m[0].curve->end(), Vector3d(5, 0, 100)));  // incremental from the start
  EXPECT_EQ(m[0].dynamics.transition, TransitionMode::Continuous);
}

TEST(Interpreter, UnmodelledCommandWarnsByName) {
  auto r = run_program("CUT3DC\nG1 X1 F100\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  bool named = false;
  for (const auto& a : r->diagnostics.items())
    if (a.severity == Severity::Warning && a.text.find("CUT3DC") != std::string::npos) named = true;
  EXPECT_TRUE(named);
}

}  // namespace
}  // namespace drycut::interp::testing

namespace drycut::interp::testing {
namespace {

TEST(Interpreter, NumberedToolAndEdgeInTheToolChangeBlock) {
  // T1 is FR_4 by number; D1 in the M6 block selects the new tool's edge (radius 2 mm).
  auto r = run_program("T1 M6 D1\nG42 G1 X10 F100\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  EXPECT_DOUBLE_EQ(r->sink.motions()[0].compensation.radius_mm, 2.0);
  auto by_default = run_program("T1\nM6\nG41 G1 X10 F100\nM30\n");
  ASSERT_FALSE(by_default->alarm) << by_default->alarm->format();
  EXPECT_DOUBLE_EQ(by_default->sink.motions()[0].compensation.radius_mm, 2.0);  // MD20270: edge 1
}

TEST(Interpreter, OffnAddsToTheToolRadiusUntilReprogrammed) {
  // Fundamentals, "OFFN": the offset path lies OFFN further from the contour (T1: radius 2 mm);
  // OFFN is modal, OFFN=0 returns to the tool radius; in inch (G70) the value is in inches.
  auto r = run_program("T1 M6 D1\nOFFN=1\nG41 G1 X10 F100\nY10\nOFFN=0.5 X0\nOFFN=0 Y0\nG40 X-10\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  const auto& m = r->sink.motions();
  ASSERT_GE(m.size(), 4u);
  EXPECT_DOUBLE_EQ(m[0].compensation.radius_mm, 3.0);
  EXPECT_DOUBLE_EQ(m[1].compensation.radius_mm, 3.0);
  EXPECT_DOUBLE_EQ(m[2].compensation.radius_mm, 2.5);
  EXPECT_DOUBLE_EQ(m[3].compensation.radius_mm, 2.0);
  auto inch = run_program("T1 M6 D1\nG70 OFFN=0.1\nG41 G1 X1 F10\nM30\n");
  ASSERT_FALSE(inch->alarm) << inch->alarm->format();
  EXPECT_NEAR(inch->sink.motions()[0].compensation.radius_mm, 2.0 + 2.54, 1e-12);
}

}  // namespace
}  // namespace drycut::interp::testing
