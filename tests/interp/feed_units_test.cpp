// Units (G70/G71/G700/G710 on metric and inch machines) and feeds (G93/G94/G95/G96, threads
// G33/G34/G35/G331/G332, G4 S). Every expected value is worked out in the comment beside it.
#include <cmath>
#include <numbers>

#include "interp_test_support.hpp"

namespace drycut::interp::testing {
namespace {

using Eigen::Vector3d;

size_t count_kind(const RunResult& r, ElementKind kind) {
  size_t n = 0;
  for (const auto& e : r.sink.elements) n += e.kind == kind;
  return n;
}

size_t count_spindle_ramps(const RunResult& r) {
  size_t n = 0;
  for (const auto& e : r.sink.elements) n += e.kind == ElementKind::Dwell && e.label == "spindle ramp";
  return n;
}

TEST(Units, MetricMachineG70ScalesGeometryNotFeed) {
  // G70 X1 = 25.4 mm, F60 stays mm/min (1 mm/s); G700 F60 is in/min = 25.4 mm/s; G71 without
  // a new F keeps the F as programmed under G700 (25.4 mm/s).
  auto r = run_program("G70 G1 X1 F60\nG700 X2 F60\nG71 X0\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  auto m = r->sink.motions();
  EXPECT_NEAR(m[0].curve->end().x(), 25.4, 1e-12);
  EXPECT_DOUBLE_EQ(m[0].feed_mm_s, 1.0);
  EXPECT_NEAR(m[1].curve->end().x(), 50.8, 1e-12);
  EXPECT_DOUBLE_EQ(m[1].feed_mm_s, 25.4);
  EXPECT_DOUBLE_EQ(m[2].feed_mm_s, 25.4);
}

TEST(Units, InchMachineFeedIsInInchUnderG70AndG71) {
  auto p = test_profile();
  p.base_unit_inch = true;
  p.reset_gcodes.push_back("G70");
  // G70 X1 F10: 25.4 mm at 10 in/min = 254/60 mm/s. G71 X10 F60: X 10 mm, F still in/min
  // (base) = 25.4 mm/s. G710 X20 F60: F in mm/min = 1 mm/s.
  auto r = run_program("G1 X1 F10\nG71 X10 F60\nG710 X20 F60\nM30\n", p);
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  auto m = r->sink.motions();
  EXPECT_NEAR(m[0].curve->end().x(), 25.4, 1e-12);
  EXPECT_NEAR(m[0].feed_mm_s, 254.0 / 60.0, 1e-12);
  EXPECT_NEAR(m[1].curve->end().x(), 10.0, 1e-12);
  EXPECT_NEAR(m[1].feed_mm_s, 25.4, 1e-12);
  EXPECT_NEAR(m[2].feed_mm_s, 1.0, 1e-12);
}

TEST(Units, CircleParametersAndThreadLeadFollowG70) {
  // G70 G2 X2 Y0 I1 J0 from X0: centre 25.4 mm away, half circle of radius 25.4 mm.
  auto r = run_program("G70 G2 X2 Y0 I1 J0 F600\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  const auto arc = r->sink.motions()[0];
  EXPECT_NEAR(arc.curve->end().x(), 50.8, 1e-9);
  EXPECT_NEAR(arc.curve->length(), std::numbers::pi * 25.4, 1e-9);
  // G70 G33 Z-1 K0.1 at S600: lead 2.54 mm, 2.54 · 600 / 60 = 25.4 mm/s.
  auto t = run_program("S600 M3\nG0 Z0\nG70 G33 Z-1 K0.1\nM30\n");
  ASSERT_FALSE(t->alarm) << t->alarm->format();
  EXPECT_NEAR(t->sink.motions()[1].feed_mm_s, 25.4, 1e-9);
}

TEST(Units, FeedPerRevolutionInInchUnderG700) {
  // G700 G95 F0.01 in/rev at 1000 rev/min: 0.254 mm · 1000 / 60 = 4.2333 mm/s.
  auto r = run_program("S1000 M3\nG700 G95 G1 X1 F0.01\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  EXPECT_NEAR(r->sink.motions()[0].feed_mm_s, 0.254 * 1000 / 60, 1e-12);
}

TEST(Feeds, InverseTimeG93GivesTheBlockTime) {
  // G93 F2: the block lasts 1/2 min; X10: 10 mm in 30 s = 1/3 mm/s. X30 (20 mm): 2/3 mm/s.
  auto r = run_program("G93 G1 X10 F2\nX30\nG94 X40 F600\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  auto m = r->sink.motions();
  EXPECT_NEAR(m[0].feed_mm_s, 10.0 * 2 / 60, 1e-12);
  EXPECT_NEAR(m[1].feed_mm_s, 20.0 * 2 / 60, 1e-12);
  EXPECT_NEAR(m[2].feed_mm_s, 10.0, 1e-12);
}

TEST(Feeds, PerRevolutionNeedsATurningSpindle) {
  auto none = run_program("G95 G1 X10 F0.1\nM30\n");
  ASSERT_TRUE(none->alarm);
  EXPECT_EQ(none->alarm->number, 10860);
  auto zero = run_program("S0 M3\nG95 G1 X10 F0.1\nM30\n");
  ASSERT_TRUE(zero->alarm);
  EXPECT_EQ(zero->alarm->number, 10860);
  // F0.1 mm/rev at 1200 rev/min = 120 mm/min = 2 mm/s.
  auto ok = run_program("S1200 M3\nG95 G1 X10 F0.1\nM30\n");
  ASSERT_FALSE(ok->alarm) << ok->alarm->format();
  EXPECT_NEAR(ok->sink.motions()[0].feed_mm_s, 2.0, 1e-12);
}

TEST(Feeds, ThreadTimeIsLengthOverLeadTimesSpeed) {
  // G33 Z-20 K1.5 at S1000 from Z0: 1.5 · 1000 = 1500 mm/min = 25 mm/s (20 mm in 0.8 s).
  auto r = run_program("S1000 M3\nG0 Z0\nG33 Z-20 K1.5\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  EXPECT_NEAR(r->sink.motions()[1].feed_mm_s, 25.0, 1e-12);
  EXPECT_EQ(r->sink.motions()[1].label, "G33");
  // Taper thread X5 Z-20 K2 at S600: 20/2 = 10 revolutions = 1 s for a path of √(25+400) mm.
  auto taper = run_program("S600 M3\nG0 X0 Z0\nG33 X5 Z-20 K2\nM30\n");
  ASSERT_FALSE(taper->alarm) << taper->alarm->format();
  EXPECT_NEAR(taper->sink.motions()[1].feed_mm_s, std::sqrt(425.0), 1e-9);
  // No lead ever programmed: alarm 14800; standing spindle: 10860.
  auto no_lead = run_program("S600 M3\nG33 Z-20\nM30\n");
  ASSERT_TRUE(no_lead->alarm);
  EXPECT_EQ(no_lead->alarm->number, 14800);
  auto stopped = run_program("S600\nG33 Z-20 K1\nM30\n");
  ASSERT_TRUE(stopped->alarm);
  EXPECT_EQ(stopped->alarm->number, 10860);
}

TEST(Feeds, VariableLeadThreads) {
  // G34 K1 F0.1 over 20 mm: 20 = N + 0.05 N² -> N = (√5 − 1)/0.1 = 12.3607 rev; at S1000 the
  // block lasts N/1000 min. It comes as pieces (one per revolution, at most 16) at their mean
  // feeds: their times add up to the block's, and the feed rises from piece to piece.
  const auto block_minutes = [](const std::vector<PathElement>& motions, const std::string& label) {
    double t = 0;
    for (const auto& m : motions)
      if (m.label == label) t += m.curve->length() / m.feed_mm_s / 60;
    return t;
  };
  auto up = run_program("S1000 M3\nG0 Z0\nG1 F600\nG34 Z-20 K1 F0.1\nG1 X5\nM30\n");
  ASSERT_FALSE(up->alarm) << up->alarm->format();
  const double n_up = (std::sqrt(5.0) - 1) / 0.1;
  const auto up_motions = up->sink.motions();
  EXPECT_NEAR(block_minutes(up_motions, "G34"), n_up / 1000, 1e-12);
  ASSERT_EQ(up_motions.size(), 1 + 13 + 1u);  // G0, 13 pieces (12.36 revolutions), G1
  EXPECT_LT(up_motions[1].feed_mm_s, up_motions[13].feed_mm_s);
  EXPECT_NEAR(up_motions[14].feed_mm_s, 10.0, 1e-12);  // the F of G34 left F600 alone
  // G35 K2 F0.1 over 10 mm: N = (2 − √2)/0.1 = 5.8579 rev; the feed falls.
  auto down = run_program("S1000 M3\nG0 Z0\nG35 Z-10 K2 F0.1\nM30\n");
  ASSERT_FALSE(down->alarm) << down->alarm->format();
  const double n_down = (2 - std::sqrt(2.0)) / 0.1;
  const auto down_motions = down->sink.motions();
  EXPECT_NEAR(block_minutes(down_motions, "G35"), n_down / 1000, 1e-12);
  EXPECT_GT(down_motions[1].feed_mm_s, down_motions.back().feed_mm_s);
  // G35 K1 F0.1 over 10 mm: 1 − 2 < 0, the lead would reach zero: alarm 14800.
  auto zero = run_program("S1000 M3\nG0 Z0\nG35 Z-10 K1 F0.1\nM30\n");
  ASSERT_TRUE(zero->alarm);
  EXPECT_EQ(zero->alarm->number, 14800);
}

TEST(Feeds, TappingAndSpindleRampDwells) {
  // spindle_ramp_time 0.5 s: two chained G33 blocks one run-up. G331 K1 at S500: 500 mm/min.
  // Rigid tapping follows the spindle's ramps in position control instead (MD35210): no dwell,
  // the Z axis's acceleration on the tapping blocks is lead · MD35210 = 1 mm · 30 rev/s² (until
  // 2026-11-29 G331 in and G332 out each got the run-up dwell, and the axis its own acceleration).
  auto p = test_profile();
  p.spindle_ramp_time_s = 0.5;
  p.spindle_posctrl_accel_rev_s2 = 30;
  auto tap = run_program("S500 M3\nG0 Z5\nG331 Z-10 K1\nG332 Z5 K1\nM30\n", p);
  ASSERT_FALSE(tap->alarm) << tap->alarm->format();
  EXPECT_EQ(count_spindle_ramps(*tap), 0u);
  const auto motions = tap->sink.motions();
  ASSERT_EQ(motions.size(), 3u);
  EXPECT_NEAR(motions[1].feed_mm_s, 500.0 / 60, 1e-12);
  for (size_t k : {1u, 2u}) {
    const double z_accel = p.axes[2].max_accel_mm_s2 * p.dynamic_groups[0].max_ax_accel * motions[k].dynamics.limits.accel[2];
    EXPECT_NEAR(z_accel, 30.0, 1e-4) << k;
    EXPECT_EQ(motions[k].dynamics.limits.accel[0], 1.0f);
  }
  EXPECT_EQ(motions[0].dynamics.limits.accel[2], 1.0f);  // the G0 before it keeps the axis's
  auto chain = run_program("S500 M3\nG0 Z5\nG33 Z0 K1\nZ-10\nM30\n", p);
  ASSERT_FALSE(chain->alarm) << chain->alarm->format();
  EXPECT_EQ(count_spindle_ramps(*chain), 1u);
}

TEST(Feeds, ConstantCuttingSpeedFollowsTheDiameter) {
  // G96 S200 (m/min) from X20 to X30: n = 200000/(2π r); the block's time at F0.1 mm/rev is
  // ∫ dr / (0.1 n) = 2π (30² − 20²) / (2 · 200000 · 0.1) min. The interpreter gives the block
  // the feed of that time; the last stage before the planner cuts it into pieces, each at its
  // own feed (speeds 1591.5 .. 1061.0 rev/min: 9 steps of at most 5 %), falling outwards; their
  // times at their feeds add up to that integral too.
  auto r = run_program("S1 M3\nG0 X20\nG96 S200\nG1 X30 F0.1\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  const double minutes = 2 * std::numbers::pi * (30.0 * 30 - 20.0 * 20) / (2 * 200000 * 0.1);
  const auto block = r->sink.motions();
  ASSERT_EQ(block.size(), 2u);
  EXPECT_NEAR(block[1].curve->length() / block[1].feed_mm_s, minutes * 60, 1e-9);
  const auto cut = with_cutting_speed_pieces(block);
  double seconds = 0;
  size_t pieces = 0;
  for (size_t k = 1; k < cut.size(); ++k) {
    seconds += cut[k].curve->length() / cut[k].feed_mm_s;
    ++pieces;
    if (k > 1) {
      EXPECT_LT(cut[k].feed_mm_s, cut[k - 1].feed_mm_s);
      EXPECT_LE(cut[k - 1].feed_mm_s / cut[k].feed_mm_s, 1.05 * 1.05);
    }
    if (!cut[k].continues_block) break;
  }
  EXPECT_EQ(pieces, 9u);  // ceil(ln(1.5) / ln(1.05)) = 9
  EXPECT_NEAR(seconds, minutes * 60, 1e-9);
  // LIMS=1000 caps it: 0.1 · 1000 / 60 mm/s.
  auto capped = run_program("S1 M3\nG0 X20\nG96 S200 LIMS=1000\nG1 X30 F0.1\nM30\n");
  ASSERT_FALSE(capped->alarm) << capped->alarm->format();
  EXPECT_NEAR(capped->sink.motions()[1].feed_mm_s, 100.0 / 60, 1e-12);
  // G97 at X25 (D 50 mm) freezes n = 200000/(50π) = 1273.2 rev/min for the next G95 block.
  auto frozen = run_program("S1 M3\nG0 X25\nG96 S200\nG97\nG1 X40 F0.1\nM30\n");
  ASSERT_FALSE(frozen->alarm) << frozen->alarm->format();
  EXPECT_NEAR(frozen->sink.motions()[1].feed_mm_s, 0.1 * 200000 / (50 * std::numbers::pi) / 60, 1e-9);
}

TEST(Feeds, ConstantCuttingSpeedPiecesComeAfterTheChamfer) {
  // G18, radius X: the face X40 -> X80 under G96 S200 F0.2 with CHR=2 into Z-20. The chamfer is
  // cut whole (legs 2 mm at the 90-degree corner: 2·√2 long, no 990015 reduction), the face
  // ends 2 mm short (X78); the pieces of that trimmed face come after it and take its time.
  auto r = run_program("G18\nS1 M3\nG0 X40 Z0\nG96 S200 LIMS=4000\nG1 X80 F0.2 CHR=2\nZ-20\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  for (const auto& a : r->diagnostics.items()) EXPECT_NE(a.number, 990015) << a.format();
  const auto m = r->sink.motions();
  ASSERT_EQ(m.size(), 4u);  // rapid, face, chamfer, Z pass
  EXPECT_NEAR(m[1].curve->end().x(), 78.0, 1e-9);
  EXPECT_NEAR(m[2].curve->length(), 2.0 * std::sqrt(2.0), 1e-9);
  ASSERT_TRUE(m[1].cutting_speed) << "the face carries its spindle speed law";
  const auto cut = with_cutting_speed_pieces(m);
  double seconds = 0;
  size_t k = 1;
  for (; k < cut.size(); ++k) {
    seconds += cut[k].curve->length() / cut[k].feed_mm_s;
    if (!cut[k].continues_block) break;
  }
  EXPECT_GT(k, 2u) << "the face comes in pieces";
  EXPECT_NEAR(cut[k].curve->end().x(), 78.0, 1e-9);
  EXPECT_NEAR(seconds, m[1].curve->length() / m[1].feed_mm_s, 1e-9);
}

TEST(Feeds, DwellInSpindleRevolutions) {
  // G4 S30 at 1200 rev/min: 30/1200 min = 1.5 s; with the spindle stopped: alarm 12160.
  auto r = run_program("S1200 M3\nG4 S30\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  size_t dwells = 0;
  for (const auto& e : r->sink.elements) {
    if (e.kind != ElementKind::Dwell) continue;
    ++dwells;
    EXPECT_NEAR(e.dwell_s, 1.5, 1e-12);
  }
  EXPECT_EQ(dwells, 1u);
  auto stopped = run_program("S1200\nG4 S30\nM30\n");
  ASSERT_TRUE(stopped->alarm);
  EXPECT_EQ(stopped->alarm->number, 12160);
}

}  // namespace
}  // namespace drycut::interp::testing
