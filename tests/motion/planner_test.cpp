// Planner against closed forms derived by hand (see each test's comment).
#include <gtest/gtest.h>

#include <cmath>

#include "machine/alarm.hpp"
#include "motion/planner.hpp"
#include "planner_test_support.hpp"

namespace drycut::motion::testing {
namespace {

using interp::ElementKind;

struct PlanRun {
  Recorder rec;
  PlanSummary summary;
};

PlanRun plan(const machine::MachineProfile& profile, std::vector<interp::PathElement> elements,
         PlannerOptions options = {}) {
  PlanRun run;
  Planner planner(profile, run.rec, options);
  for (auto& e : elements) planner.consume(std::move(e));
  planner.finish();
  run.summary = planner.summary();
  return run;
}

const Vec3 O = Vec3::Zero();

TEST(Limit, Names) {
  EXPECT_EQ(to_string(Limit::Feed), "feed");
  EXPECT_EQ(to_string(Limit::Curvature), "curvature");
  EXPECT_EQ(to_string(Limit::Jerk), "jerk");
  EXPECT_EQ(to_string(Limit::Corner), "corner");
  EXPECT_EQ(to_string(Limit::ShortBlock), "short_block");
  EXPECT_EQ(to_string(Limit::Lookahead), "lookahead");
  EXPECT_EQ(to_string(Limit::ExactStop), "exact_stop");
  EXPECT_EQ(to_string(Limit::Axis), "axis");
}

TEST(Planner, LongLineBriskIsATrapezoid) {
  // Rest to rest at F6000 = 100 mm/s, a = 5000: t = L/v + v/a.
  PlanRun r = plan(plain_profile(), {line(O, Vec3(1000, 0, 0), 6000)});
  ASSERT_EQ(r.rec.blocks.size(), 1u);
  EXPECT_NEAR(r.summary.time_s, 1000.0 / 100.0 + 100.0 / 5000.0, 1e-9);
  EXPECT_NEAR(r.rec.blocks[0].v_max_mm_s, 100.0, 1e-9);
  EXPECT_NEAR(r.summary.path_length_mm, 1000.0, 1e-9);
  EXPECT_NEAR(r.summary.max_feed_mm_s, 100.0, 1e-9);
  EXPECT_TRUE(r.summary.dips.empty());
}

TEST(Planner, ShortLineBriskIsATriangle) {
  // 1 mm from rest to rest with no cruise: peak = sqrt(a·L), t = 2·sqrt(L/a).
  PlanRun r = plan(plain_profile(), {line(O, Vec3(1, 0, 0), 30000)});
  EXPECT_NEAR(r.summary.time_s, 2.0 * std::sqrt(1.0 / 5000.0), 1e-9);
  EXPECT_NEAR(r.rec.blocks[0].v_max_mm_s, std::sqrt(5000.0), 1e-9);
}

TEST(Planner, LongLineSoftWithoutConstantAccelerationPhase) {
  // j = min(path 40000, axis 50000) = 40000; v = 100 < a²/j = 625, so each ramp lasts
  // 2·sqrt(v/j) and covers v/2 of that time: t = L/v + 2·sqrt(v/j).
  PlanRun r = plan(plain_profile(), {line(O, Vec3(1000, 0, 0), 6000, Mode{.soft = true})});
  EXPECT_NEAR(r.summary.time_s, 10.0 + 2.0 * std::sqrt(100.0 / 40000.0), 1e-9);
}

TEST(Planner, LongLineSoftWithConstantAccelerationPhase) {
  // a = 1000 (axis 1000, SOFT factor 1), j = 40000: v = 100 >= a²/j = 25; a ramp lasts
  // T = v/a + a/j at mean speed v/2, so t = L/v + v/a + a/j.
  auto p = plain_profile();
  for (auto& a : p.axes) a.max_accel_mm_s2 = 1000;
  PlanRun r = plan(p, {line(O, Vec3(1000, 0, 0), 6000, Mode{.soft = true})});
  EXPECT_NEAR(r.summary.time_s, 10.0 + 0.1 + 0.025, 1e-9);
}

TEST(Planner, SoftAccelFactorScalesAcceleration) {
  // BRISK-like check through SOFT: factor 0.2 on a = 5000 gives a = 1000 as above.
  auto p = plain_profile();
  p.soft_accel_factor = 0.2;
  PlanRun r = plan(p, {line(O, Vec3(1000, 0, 0), 6000, Mode{.soft = true})});
  EXPECT_NEAR(r.summary.time_s, 10.0 + 0.1 + 0.025, 1e-9);
}

// Time of a BRISK element from v0 up to v and down to v1 over L (hand formula).
double trapezoid(double L, double v0, double v, double v1, double a) {
  const double d_up = (v * v - v0 * v0) / (2 * a), d_down = (v * v - v1 * v1) / (2 * a);
  return (v - v0) / a + (v - v1) / a + (L - d_up - d_down) / v;
}

TEST(Planner, RightAngleCornerUnderG64UsesTheOverloadRule) {
  // X then Y: each axis jumps by the full path speed, so v_corner = a·(OVL-1)·T_IPO
  // = 5000·0.2·0.004 = 4 mm/s.
  PlanRun r = plan(plain_profile(), {line(O, Vec3(100, 0, 0), 6000, {}, 1),
                                 line(Vec3(100, 0, 0), Vec3(100, 100, 0), 6000, {}, 2)});
  ASSERT_EQ(r.rec.blocks.size(), 2u);
  const double vc = 4.0;
  EXPECT_NEAR(r.rec.blocks[0].v_min_mm_s, 0.0, 1e-12);  // starts at rest
  EXPECT_EQ(r.rec.blocks[0].limit, Limit::ExactStop);
  EXPECT_NEAR(r.rec.blocks[0].time_s, trapezoid(100, 0, 100, vc, 5000), 1e-9);
  EXPECT_NEAR(r.rec.blocks[1].time_s, trapezoid(100, vc, 100, 0, 5000), 1e-9);
  ASSERT_EQ(r.summary.dips.size(), 1u);
  EXPECT_NEAR(r.summary.dips[0].v_min_mm_s, vc, 1e-9);
  EXPECT_EQ(r.summary.dips[0].limit, Limit::Corner);
  EXPECT_EQ(r.summary.dips[0].element_count, 2u);
  EXPECT_NEAR(r.summary.min_feed_mm_s, vc, 1e-9);
}

TEST(Planner, RightAngleCornerUnderG60Stops) {
  Mode g60{.exact_stop = true};
  PlanRun r = plan(plain_profile(), {line(O, Vec3(100, 0, 0), 6000, g60),
                                 line(Vec3(100, 0, 0), Vec3(100, 100, 0), 6000, g60)});
  EXPECT_NEAR(r.rec.blocks[0].time_s, 1.0 + 0.02, 1e-9);
  EXPECT_NEAR(r.rec.blocks[1].time_s, 1.0 + 0.02, 1e-9);
  EXPECT_EQ(r.rec.blocks[0].limit, Limit::ExactStop);
  EXPECT_TRUE(r.summary.dips.empty());  // planned standstills are not dips
}

TEST(Planner, G9StopsOneBlockInContinuousMode) {
  auto first = line(O, Vec3(100, 0, 0), 6000);
  first.dynamics.exact_stop_this_block = true;
  PlanRun r = plan(plain_profile(), {first, line(Vec3(100, 0, 0), Vec3(200, 0, 0), 6000)});
  EXPECT_NEAR(r.summary.time_s, 2 * (1.0 + 0.02), 1e-9);
}

TEST(Planner, TangentTransitionKeepsSpeed) {
  PlanRun r = plan(plain_profile(), {line(O, Vec3(100, 0, 0), 6000), line(Vec3(100, 0, 0), Vec3(200, 0, 0), 6000)});
  EXPECT_NEAR(r.summary.time_s, 2.0 + 0.02, 1e-9);
  EXPECT_NEAR(r.rec.blocks[0].v_min_mm_s, 0.0, 1e-12);
  EXPECT_NEAR(r.rec.blocks[1].v_min_mm_s, 0.0, 1e-12);
}

TEST(Planner, CircleAtTheCurvatureLimit) {
  // Full circle r = 10 at F20000 (333 mm/s). Where the normal is along X, axis X carries
  // the whole centripetal acceleration: v² = share·a·r -> v = sqrt(0.75·5000·10).
  auto arc = std::make_shared<TestArc>(O, 10.0, 0.0, 2 * M_PI);
  PlanRun r = plan(plain_profile(), {motion(arc, 20000, {}, ElementKind::Arc)});
  const double v = std::sqrt(0.75 * 5000 * 10);
  ASSERT_EQ(r.summary.dips.size(), 1u);
  EXPECT_NEAR(r.summary.dips[0].v_min_mm_s, v, 1e-9);
  EXPECT_EQ(r.summary.dips[0].limit, Limit::Curvature);
  EXPECT_NEAR(r.summary.min_feed_mm_s, v, 1e-9);
  // Nowhere faster than the best-case limit (normal at 45°: share·a·r·sqrt(2)).
  EXPECT_LE(r.rec.blocks[0].v_max_mm_s, std::sqrt(0.75 * 5000 * 10 * std::sqrt(2.0)) + 1e-9);
}

TEST(Planner, CircleUnderSoftAtTheJerkLimit) {
  // At constant speed the axis jerk on a circle is v³/r² on the axis along the tangent:
  // v = cbrt(j·r²) = cbrt(50000·100) < the curvature limit 193.6.
  auto arc = std::make_shared<TestArc>(O, 10.0, 0.0, 2 * M_PI);
  PlanRun r = plan(plain_profile(), {motion(arc, 20000, Mode{.soft = true}, ElementKind::Arc)});
  ASSERT_EQ(r.summary.dips.size(), 1u);
  EXPECT_NEAR(r.summary.dips[0].v_min_mm_s, std::cbrt(50000.0 * 100.0), 1e-9);
  EXPECT_EQ(r.summary.dips[0].limit, Limit::Jerk);
}

TEST(Planner, ShortBlocksAtF10000) {
  // 0.05 mm collinear blocks: v = 0.9·0.05/0.004 = 11.25 mm/s (675 mm/min) whatever F is.
  std::vector<interp::PathElement> elements;
  for (int i = 0; i < 1000; ++i)
    elements.push_back(line(Vec3(0.05 * i, 0, 0), Vec3(0.05 * (i + 1), 0, 0), 10000, {}, i + 1));
  PlanRun r = plan(plain_profile(), std::move(elements));
  const double v = 0.9 * 0.05 / 0.004;
  EXPECT_NEAR(r.summary.min_feed_mm_s, v, 1e-9);
  EXPECT_NEAR(r.summary.max_feed_mm_s, v, 1e-9);
  // Both ramps (v²/2a = 0.0127 mm) fit in the first and last block: t = L/v + v/a.
  EXPECT_NEAR(r.summary.time_s, 50.0 / v + v / 5000.0, 1e-9);
  ASSERT_EQ(r.summary.dips.size(), 1u);
  EXPECT_EQ(r.summary.dips[0].limit, Limit::ShortBlock);
  EXPECT_EQ(r.summary.dips[0].element_count, 1000u);
  EXPECT_EQ(r.summary.dips[0].source.line, 1u);
}

TEST(Planner, LookaheadWindowEndsAtRest) {
  // Window of 4 blocks of 1 mm beyond the committed one: its end node is 4 mm before a
  // stop, so v = sqrt(2·a·4 mm) = 200 mm/s; inside the block the peak is
  // sqrt((2·a·L + 2·200²)/2).
  std::vector<interp::PathElement> elements;
  for (int i = 0; i < 40; ++i) elements.push_back(line(Vec3(i, 0, 0), Vec3(i + 1, 0, 0), 36000));
  PlanRun r = plan(plain_profile(4), std::move(elements));
  const BlockTiming& mid = r.rec.blocks[20];
  EXPECT_NEAR(mid.v_min_mm_s, 200.0, 1e-9);
  EXPECT_EQ(mid.limit, Limit::Lookahead);
  EXPECT_NEAR(mid.v_max_mm_s, std::sqrt(45000.0), 1e-9);
  EXPECT_NEAR(mid.time_s, trapezoid(1.0, 200, std::sqrt(45000.0), 200, 5000), 1e-12);
}

TEST(Planner, DwellAddsExactlyItsTime) {
  auto dwell = passive(ElementKind::Dwell, "G4");
  dwell.dwell_s = 2.5;
  PlanRun r = plan(plain_profile(), {line(O, Vec3(10, 0, 0), 600), dwell, line(Vec3(10, 0, 0), O, 600)});
  // Each 10 mm line at 10 mm/s from rest to rest: 1 + 10/5000.
  ASSERT_EQ(r.rec.blocks.size(), 3u);
  EXPECT_DOUBLE_EQ(r.rec.blocks[1].time_s, 2.5);
  EXPECT_NEAR(r.summary.time_s, 2 * 1.002 + 2.5, 1e-9);
}

TEST(Planner, SpindleRunUpWaitCountsFromTheElementThatBeganTheRamp) {
  // The ramp (2 s into range) begins with the first of two lines (1.002 s each, rest to rest:
  // 1 + 10/5000); the wait is 2 - 2.004 < 0: none, whatever the interpreter's estimate (9 s).
  // A second ramp of 3 s begins with a line of 1.002 s: the wait is 3 - 1.002 = 1.998 s.
  auto first = line(O, Vec3(10, 0, 0), 600);
  first.run_up_start = 1;
  auto wait = passive(ElementKind::Dwell, "waiting for the spindle speed (MD35500)");
  wait.dwell_s = 9.0;
  wait.run_up_wait = 1;
  wait.run_up_s = 2.0;
  auto second = line(Vec3(10, 0, 0), O, 600);
  second.run_up_start = 2;
  auto wait2 = wait;
  wait2.run_up_wait = 2;
  wait2.run_up_s = 3.0;
  // A wait whose ramp's first element never reached the planner keeps the estimate.
  auto orphan = wait;
  orphan.run_up_wait = 7;
  orphan.dwell_s = 0.25;
  auto exact = [](auto e) {
    e.dynamics.exact_stop_this_block = true;
    return e;
  };
  PlanRun r = plan(plain_profile(), {exact(first), exact(line(Vec3(10, 0, 0), O, 600)), wait, exact(second), wait2, orphan});
  ASSERT_EQ(r.rec.blocks.size(), 6u);
  EXPECT_DOUBLE_EQ(r.rec.blocks[2].time_s, 0.0);
  EXPECT_NEAR(r.rec.blocks[4].time_s, 3.0 - 1.002, 1e-9);
  EXPECT_DOUBLE_EQ(r.rec.blocks[5].time_s, 0.25);
}

TEST(Planner, ToolChangeAddsTheProfileTime) {
  PlanRun r = plan(plain_profile(), {passive(ElementKind::ToolChange, "M6"), line(O, Vec3(10, 0, 0), 600)});
  EXPECT_DOUBLE_EQ(r.rec.blocks[0].time_s, 3.0);
  EXPECT_NEAR(r.summary.time_s, 3.0 + 1.002, 1e-9);
}

TEST(Planner, TimeAfterFirstM0) {
  auto m0 = passive(ElementKind::Stop, "M0");
  m0.stop = interp::StopKind::ProgramStop;
  PlanRun r = plan(plain_profile(), {line(O, Vec3(10, 0, 0), 600), m0, line(Vec3(10, 0, 0), O, 600), m0});
  ASSERT_EQ(r.rec.blocks.size(), 4u);
  EXPECT_FALSE(r.rec.blocks[0].after_first_m0);
  EXPECT_TRUE(r.rec.blocks[2].after_first_m0);
  EXPECT_DOUBLE_EQ(r.rec.blocks[1].time_s, 0.0);
  EXPECT_NEAR(r.summary.time_after_m0_s, 1.002, 1e-9);
  EXPECT_NEAR(r.summary.time_s, 2 * 1.002, 1e-9);
}

TEST(Planner, FeedWhileCuttingCountsABlockBetweenStandstillsAtItsTopSpeed) {
  // One line from rest to rest at F600 (10 mm/s): no velocity outside its planned ramps, yet it
  // cut at 10 mm/s; it is not a dip.
  PlanRun r = plan(plain_profile(), {line(O, Vec3(10, 0, 0), 600)});
  EXPECT_NEAR(r.summary.min_feed_mm_s, 10.0, 1e-9);
  EXPECT_NEAR(r.summary.max_feed_mm_s, 10.0, 1e-9);
  EXPECT_TRUE(r.summary.dips.empty());
}

TEST(Planner, NoM0MeansNoTimeAfterM0) {
  PlanRun r = plan(plain_profile(), {line(O, Vec3(10, 0, 0), 600)});
  EXPECT_EQ(r.summary.time_after_m0_s, 0.0);
}

TEST(Planner, RapidRunsAtTheProjectedAxisVelocity) {
  // Diagonal in XY: each axis at 40 m/min, path = 666.7·sqrt(2).
  PlanRun r = plan(plain_profile(), {rapid(O, Vec3(500, 500, 0))});
  EXPECT_NEAR(r.rec.blocks[0].v_max_mm_s, 40000.0 / 60.0 * std::sqrt(2.0), 1e-9);
  EXPECT_TRUE(r.rec.blocks[0].rapid);
  EXPECT_EQ(r.summary.max_feed_mm_s, 0.0);  // no cutting
  EXPECT_EQ(r.summary.min_feed_mm_s, 0.0);
  // a_t = 5000/cos45 on this diagonal; v = 942.8, L = 707.1: t = L/v + v/a_t.
  const double v = 40000.0 / 60.0 * std::sqrt(2.0), a = 5000 * std::sqrt(2.0);
  EXPECT_NEAR(r.summary.time_s, 500 * std::sqrt(2.0) / v + v / a, 1e-9);
}

TEST(Planner, G0AccelFactorScalesRapidAcceleration) {
  auto p = plain_profile();
  p.g0_accel_factor = 0.5;
  PlanRun r = plan(p, {rapid(O, Vec3(500, 0, 0))});
  const double v = 40000.0 / 60.0;
  EXPECT_NEAR(r.summary.time_s, 500 / v + v / 2500.0, 1e-9);
}

TEST(Planner, EmitsSamplesEveryIpoCycle) {
  PlannerOptions o;
  o.emit_samples = true;
  PlanRun r = plan(plain_profile(), {line(O, Vec3(100, 0, 0), 6000)}, o);
  ASSERT_GT(r.rec.samples.size(), 200u);
  for (size_t i = 0; i < r.rec.samples.size(); ++i)
    EXPECT_NEAR(r.rec.samples[i].t_s, 0.004 * static_cast<double>(i), 1e-12);
  // Mid-way through the cruise: x = v·t - v²/(2a) with the ramp's lag.
  const auto& s = r.rec.samples[250];
  EXPECT_NEAR(s.v_mm_s, 100.0, 1e-9);
  EXPECT_NEAR(s.position.x(), 100.0 * 1.0 - 100.0 * 100.0 / (2 * 5000), 1e-9);
  EXPECT_NEAR(r.rec.samples.back().position.x(), 100.0, 0.05);
}

TEST(Planner, BadInputRaisesAlarms) {
  auto expect_alarm = [](interp::PathElement e, int number) {
    Recorder rec;
    Planner planner(plain_profile(), rec);
    try {
      planner.consume(std::move(e));
      planner.finish();
      ADD_FAILURE() << "no alarm " << number;
    } catch (const AlarmError& err) {
      EXPECT_EQ(err.alarm().number, number);
    }
  };
  expect_alarm(line(O, Vec3(1, 0, 0), 0), 10860);
  expect_alarm(line(O, Vec3(1, 0, 0), -5), 14800);
  expect_alarm(line(O, Vec3(1, 0, 0), std::nan("")), 10860);
  auto no_curve = line(O, Vec3(1, 0, 0), 100);
  no_curve.curve = nullptr;
  expect_alarm(no_curve, 990020);
  auto dwell = passive(ElementKind::Dwell, "G4");
  dwell.dwell_s = -1;
  expect_alarm(dwell, 12160);
  expect_alarm(line(O, Vec3(1, 0, 0), 1e-320), 14800);  // denormal F: infinite time
  expect_alarm(line(O, Vec3(std::nan(""), 0, 0), 100), 990020);
  auto huge = std::make_shared<TestArc>(O, 1e12, 0.0, 1.0);  // 1e12 mm: bounded discretisation
  Recorder rec;
  Planner planner(plain_profile(), rec);
  planner.consume(motion(huge, 6000, {}, ElementKind::Arc));
  planner.finish();
  EXPECT_GT(planner.summary().time_s, 1e12 / 100.0 * (1 - 1e-9));
}

TEST(Planner, ZeroLengthElementsAndDynamicsChangesPassThrough) {
  PlanRun r = plan(plain_profile(), {line(O, Vec3(100, 0, 0), 6000), line(Vec3(100, 0, 0), Vec3(100, 0, 0), 6000),
                                 passive(ElementKind::DynamicsChange, "SOFT"),
                                 line(Vec3(100, 0, 0), Vec3(200, 0, 0), 6000)});
  ASSERT_EQ(r.rec.blocks.size(), 4u);
  EXPECT_EQ(r.rec.blocks[1].time_s, 0.0);
  EXPECT_EQ(r.rec.blocks[2].label, "SOFT");
  // The zero-length block does not break the straight path.
  EXPECT_NEAR(r.summary.time_s, 2.0 + 0.02, 1e-9);
  EXPECT_EQ(r.summary.elements, 4u);
}

TEST(Planner, DipsAreBoundedAndCounted) {
  // 30 corners, each between two cutting blocks (one merged dip), separated by rapids
  // (not cutting: they end a stretch). Keep only 10 and count the other 20.
  std::vector<interp::PathElement> elements;
  Vec3 p = O;
  for (int i = 0; i < 30; ++i) {
    elements.push_back(line(p, p + Vec3(10, 0, 0), 6000, {}, 3 * i + 1));
    elements.push_back(line(p + Vec3(10, 0, 0), p + Vec3(10, 10, 0), 6000, {}, 3 * i + 2));
    elements.push_back(rapid(p + Vec3(10, 10, 0), p + Vec3(0, 20, 0)));
    p += Vec3(0, 20, 0);
  }
  PlannerOptions o;
  o.max_dips = 10;
  PlanRun r = plan(plain_profile(), std::move(elements), o);
  ASSERT_EQ(r.summary.dips.size(), 10u);
  EXPECT_EQ(r.summary.dips_not_listed, 20u);
  EXPECT_EQ(r.summary.dips[3].element_count, 2u);
  EXPECT_EQ(r.summary.dips[3].source.line, 10u);
  EXPECT_EQ(r.summary.dips[3].limit, Limit::Corner);
}

TEST(Planner, PiecesOfOneBlockAreReportedAsOneBlock) {
  // A block in two collinear pieces (a G96 cut at its changing feeds: F3000, then F6000) is one
  // timing: the pieces' times and lengths added, the highest and lowest velocity of both. BRISK,
  // a = 5000: 0 -> 50 mm/s (0.25 mm, 0.01 s), 50 -> 100 mm/s at the join (0.75 mm, 0.01 s),
  // 100 -> 0 (1 mm, 0.02 s): t = 0.01 + 99.75/50 + 0.01 + 98.25/100 + 0.02 = 3.0175 s.
  interp::PathElement first = line(O, Vec3(100, 0, 0), 3000, {}, 7);
  first.continues_block = true;
  PlanRun r = plan(plain_profile(), {first, line(Vec3(100, 0, 0), Vec3(200, 0, 0), 6000, {}, 7)});
  ASSERT_EQ(r.rec.blocks.size(), 1u);
  EXPECT_EQ(r.rec.blocks[0].source.line, 7u);
  EXPECT_NEAR(r.rec.blocks[0].length_mm, 200.0, 1e-9);
  EXPECT_NEAR(r.rec.blocks[0].time_s, 3.0175, 1e-9);
  EXPECT_NEAR(r.rec.blocks[0].v_max_mm_s, 100.0, 1e-9);
  EXPECT_NEAR(r.summary.time_s, 3.0175, 1e-9);
}

}  // namespace
}  // namespace drycut::motion::testing
