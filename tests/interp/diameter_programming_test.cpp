// Diameter programming for turning (DIAMON/DIAM90/DIAMOF/DIAMCYCOF, DIAMONA[ax] ... with MD20100)
// and SCC[ax]. Every expected value is worked out in the comment beside it; the rules are in
// docs/controller-state.md "Diameter programming".
#include "interp/diameter_programming.hpp"

#include <string>

#include "interp_test_support.hpp"

namespace drycut::interp::testing {
namespace {

// The test machine as a lathe: X is the transverse axis (MD20100), G18, no tool length, G54 zero.
machine::MachineProfile lathe_profile() {
  auto p = test_profile();
  p.diameter_axis = "X";
  p.reset_gcodes.push_back("G18");
  p.work_offsets.clear();
  p.tools = {{"TURN", 1, {{1, 0.0, 0.0}}}};
  p.start_position = Eigen::Vector3d(0, 0, 0);
  return p;
}

bool has_warning(const RunResult& r, int number, const std::string& part) {
  for (const auto& a : r.diagnostics.items())
    if (a.severity == Severity::Warning && a.number == number && a.text.find(part) != std::string::npos) return true;
  return false;
}

TEST(DiameterState, PositionFactorPerMode) {
  DiameterState d;
  d.transverse_axis = 0;
  d.channel = DiameterMode::On;  // diameter for absolute and incremental values
  EXPECT_EQ(d.position_factor(0, false), 0.5);
  EXPECT_EQ(d.position_factor(0, true), 0.5);
  EXPECT_EQ(d.position_factor(2, false), 1.0);  // Z is no transverse axis
  d.channel = DiameterMode::Absolute90;  // diameter only for absolute values
  EXPECT_EQ(d.position_factor(0, false), 0.5);
  EXPECT_EQ(d.position_factor(0, true), 1.0);
  d.channel = DiameterMode::CycleOff;
  EXPECT_EQ(d.position_factor(0, false), 1.0);
  d.axis[2] = DiameterMode::On;  // DIAMONA[Z]: its own mode
  EXPECT_EQ(d.position_factor(2, true), 0.5);
  d.transverse_axis = -1;  // no MD20100: the channel mode acts on no axis
  d.channel = DiameterMode::On;
  EXPECT_EQ(d.position_factor(0, false), 1.0);
}

TEST(DiameterProgramming, DiamonHalvesAbsoluteAndIncrementalValues) {
  // X40 -> radius 20; G91 X-10 -> 15; X=AC(50) -> 25; G90 X=IC(-10) -> 20. Z stays a radius axis.
  auto r = run_program("DIAMON G0 X40 Z-5\nG91 X-10\nX=AC(50)\nG90 X=IC(-10) Z=IC(-5)\nM30\n", lathe_profile());
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  auto m = r->sink.motions();
  ASSERT_EQ(m.size(), 4u);
  EXPECT_NEAR(m[0].curve->end().x(), 20.0, 1e-12);
  EXPECT_NEAR(m[0].curve->end().z(), -5.0, 1e-12);
  EXPECT_NEAR(m[1].curve->end().x(), 15.0, 1e-12);
  EXPECT_NEAR(m[2].curve->end().x(), 25.0, 1e-12);
  EXPECT_NEAR(m[3].curve->end().x(), 20.0, 1e-12);
  EXPECT_NEAR(m[3].curve->end().z(), -10.0, 1e-12);
}

TEST(DiameterProgramming, Diam90IsDiameterOnlyForAbsoluteValues) {
  // X40 -> 20; G91 X4 (radius) -> 24; X=AC(30) -> 15; G90 X=IC(2) (radius) -> 17; DIAMOF X10 -> 10.
  auto r = run_program("DIAM90 G0 X40\nG91 X4\nX=AC(30)\nG90 X=IC(2)\nDIAMOF X10\nM30\n", lathe_profile());
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  auto m = r->sink.motions();
  ASSERT_EQ(m.size(), 5u);
  EXPECT_NEAR(m[0].curve->end().x(), 20.0, 1e-12);
  EXPECT_NEAR(m[1].curve->end().x(), 24.0, 1e-12);
  EXPECT_NEAR(m[2].curve->end().x(), 15.0, 1e-12);
  EXPECT_NEAR(m[3].curve->end().x(), 17.0, 1e-12);
  EXPECT_NEAR(m[4].curve->end().x(), 10.0, 1e-12);
}

TEST(DiameterProgramming, ResetDefaultFromTheProfile) {
  // MD20150 group 29 = DIAMON: X40 at program start is a diameter.
  auto p = lathe_profile();
  p.reset_gcodes.push_back("DIAMON");
  auto r = run_program("G0 X40\nM30\n", p);
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  EXPECT_NEAR(r->end_position.x(), 20.0, 1e-12);
}

TEST(DiameterProgramming, CircleRadiusAndIncrementalCentreAreRadii) {
  // (r10, z0) -> (r20, z-10) with CR=10: chord 14.14 < 20, no 14040 (X as radius: chord 22.4).
  // G3 X60 Z-20 I0 K-10: centre (r20, z-20), end (r30, z-20), radius 10. G3 X40 Z-30 I=AC(40)
  // K=AC(-20): centre (r20, z-20) from a diameter, end (r20, z-30), a quarter circle on.
  auto r = run_program("DIAMON G0 X20 Z0\nG2 X40 Z-10 CR=10 F1000\nG3 X60 Z-20 I0 K-10\nG3 X40 Z-30 I=AC(40) K=AC(-20)\nM30\n",
                       lathe_profile());
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  auto m = r->sink.motions();
  ASSERT_EQ(m.size(), 4u);
  EXPECT_NEAR(m[1].curve->end().x(), 20.0, 1e-9);
  EXPECT_NEAR(m[1].curve->end().z(), -10.0, 1e-9);
  EXPECT_NEAR(m[2].curve->end().x(), 30.0, 1e-9);
  EXPECT_NEAR(m[3].curve->end().x(), 20.0, 1e-9);
  EXPECT_NEAR(m[3].curve->end().z(), -30.0, 1e-9);
  // Quarter circles of radius 10: length 5*pi each.
  EXPECT_NEAR(m[2].curve->length(), 5.0 * std::numbers::pi, 1e-6);
  EXPECT_NEAR(m[3].curve->length(), 5.0 * std::numbers::pi, 1e-6);
}

TEST(DiameterProgramming, CipIntermediatePointIsAPosition) {
  // Circle about (r0, z0) radius 10 in G18: from (r10, z0) through (r7.0711, z-7.0711) to
  // (r0, z-10); the intermediate X is a diameter 14.1421.
  auto r = run_program("DIAMON G0 X20 Z0\nCIP X0 Z-10 I1=14.142136 K1=-7.071068 F1000\nM30\n", lathe_profile());
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  auto m = r->sink.motions();
  ASSERT_EQ(m.size(), 2u);
  EXPECT_NEAR(m[1].curve->length(), 5.0 * std::numbers::pi, 1e-5);
}

TEST(DiameterProgramming, AxisSpecificCommandsOverrideTheChannel) {
  // DIAMONA[X] under DIAMOF: X40 -> 20. DIAMCHANA[X]: the channel's DIAMOF -> X30 is 30.
  // DIAMONA[Z] (a second axis in diameter): Z-20 -> -10. DIAMCHAN: all back to the channel.
  auto r = run_program("DIAMOF DIAMONA[X] G0 X40\nDIAMCHANA[X] X30\nDIAMONA[Z] Z-20\nDIAMCHAN Z-20\nM30\n",
                       lathe_profile());
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  auto m = r->sink.motions();
  ASSERT_EQ(m.size(), 4u);
  EXPECT_NEAR(m[0].curve->end().x(), 20.0, 1e-12);
  EXPECT_NEAR(m[1].curve->end().x(), 30.0, 1e-12);
  EXPECT_NEAR(m[2].curve->end().z(), -10.0, 1e-12);
  EXPECT_NEAR(m[3].curve->end().z(), -20.0, 1e-12);
}

TEST(DiameterProgramming, SaveRestoresTheModeAfterACycle) {
  // The cycle (PROC ... SAVE) works in radius with DIAMCYCOF; after it DIAMON is back: X40 -> 20.
  auto r = run_program("DIAMON G0 X20\nMYCYC\nX40\nM30\n", lathe_profile(),
                       {{"MYCYC", "PROC MYCYC SAVE\nDIAMCYCOF\nG0 X30\nRET\n"}});
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  auto m = r->sink.motions();
  ASSERT_EQ(m.size(), 3u);
  EXPECT_NEAR(m[0].curve->end().x(), 10.0, 1e-12);
  EXPECT_NEAR(m[1].curve->end().x(), 30.0, 1e-12);
  EXPECT_NEAR(m[2].curve->end().x(), 20.0, 1e-12);
}

TEST(DiameterProgramming, MillingProfileWithoutTransverseAxisWarns) {
  // No MD20100: DIAMON has no axis to act on; X40 stays 40 and a warning names it.
  auto r = run_program("DIAMON G0 X40\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  EXPECT_NEAR(r->end_position.x(), 40.0, 1e-12);
  EXPECT_TRUE(has_warning(*r, 990002, "DIAMON without a transverse axis"));
}

TEST(DiameterProgramming, AxisSpecificOnAnUnknownAxisIsAnError) {
  // DIAMONA[Q]: Q is no axis of the channel (alarm 12550); an axis letter the profile lacks warns.
  auto bad = run_program("DIAMONA[Q]\nM30\n", lathe_profile());
  ASSERT_TRUE(bad->alarm);
  EXPECT_EQ(bad->alarm->number, 12550);
  auto missing = run_program("DIAMONA[U]\nM30\n", lathe_profile());
  ASSERT_FALSE(missing->alarm) << missing->alarm->format();
  EXPECT_TRUE(has_warning(*missing, 990002, "DIAMONA[U]"));
}

TEST(ConstantCuttingSpeed, SccNamesTheReferenceAxis) {
  // G96 S100 (m/min) with the tool at Z-10 (radius 10 on the SCC axis Z): n = 100000/(pi*20)
  // = 1591.55 rev/min; F0.1 mm/rev -> 159.155 mm/min = 2.65258 mm/s. With X (at 0) it would
  // be the centre: MD35100 10000 rev/min.
  auto r = run_program("G0 Z-10\nSCC[Z]\nS500 M3\nG96 S100\nG1 X5 F0.1\nM30\n", lathe_profile());
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  auto m = r->sink.motions();
  ASSERT_EQ(m.size(), 2u);
  EXPECT_NEAR(m[1].feed_mm_s, 100000.0 / (std::numbers::pi * 20.0) * 0.1 / 60.0, 1e-9);
}

}  // namespace
}  // namespace drycut::interp::testing
