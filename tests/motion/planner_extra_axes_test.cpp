// Planner with synchronized extra axes and positioning axes (planner.hpp step 7, docs/axes.md),
// against closed forms derived by hand in each test's comment.
#include <gtest/gtest.h>

#include <cmath>

#include "motion/path_constraints.hpp"
#include "motion/planner.hpp"
#include "motion/positioning_axes.hpp"
#include "interp/rest_to_rest.hpp"
#include "planner_test_support.hpp"

namespace drycut::motion::testing {
namespace {

using interp::ElementKind;

// plain_profile plus a rotary A: 60 deg/s, 600 deg/s², jerk 6000 deg/s³.
machine::MachineProfile rotary_profile() {
  machine::MachineProfile p = plain_profile();
  machine::AxisData a;
  a.name = "A";
  a.rotary = true;
  a.max_velocity_mm_s = 60;
  a.max_accel_mm_s2 = 600;
  a.max_jerk_mm_s3 = 6000;
  a.transition_jerk_mm_s3 = 6000;
  p.extra_axes.push_back(a);
  return p;
}

interp::PathElement with_a(interp::PathElement e, double start, double travel, bool grouped = false) {
  e.extra_axes.push_back({0, "A", start, travel, grouped});
  return e;
}

double plan_time(const machine::MachineProfile& profile, std::vector<interp::PathElement> elements) {
  Recorder rec;
  Planner planner(profile, rec);
  for (auto& e : elements) planner.consume(std::move(e));
  planner.finish();
  return planner.summary().time_s;
}

const Vec3 O = Vec3::Zero();

TEST(PlannerExtraAxes, SlowRotaryAxisCapsThePathVelocity) {
  // X 30 mm with A 40 deg, F6000 (100 mm/s), BRISK, rest to rest. A moves 4/3 deg per mm:
  // v <= 60 / (4/3) = 45 mm/s; a_t = min(5000, 600 / (4/3) = 450) = 450: t = 30/45 + 45/450.
  const double t = plan_time(rotary_profile(), {with_a(line(O, Vec3(30, 0, 0), 6000), 0, 40)});
  EXPECT_NEAR(t, 30.0 / 45.0 + 45.0 / 450.0, 1e-9);
}

TEST(PlannerExtraAxes, GroupedAxisCountsInThePathLength) {
  // FGROUP(X, A): L = sqrt(30² + 40²) = 50, F3000 = 50/s; shares 0.6 (X) and 0.8 (A):
  // A at 40 deg/s <= 60; a_t = min(5000/0.6, 600/0.8 = 750): t = 50/50 + 50/750.
  const double t = plan_time(rotary_profile(), {with_a(line(O, Vec3(30, 0, 0), 3000), 0, 40, true)});
  EXPECT_NEAR(t, 1.0 + 50.0 / 750.0, 1e-9);
}

TEST(PlannerExtraAxes, RotaryAloneIsPlannedInDegrees) {
  // No geometry travel: the path is A's 90 deg at F1800 = 30 deg/s: t = 90/30 + 30/600.
  const double t = plan_time(rotary_profile(), {with_a(line(O, O, 1800), 0, 90)});
  EXPECT_NEAR(t, 3.0 + 0.05, 1e-9);
}

// Time over length L from v0 through cruise v to v1 with acceleration a (BRISK), all reachable.
double trapezoid(double L, double v0, double v, double v1, double a) {
  const double d_up = (v * v - v0 * v0) / (2 * a), d_down = (v * v - v1 * v1) / (2 * a);
  return (v - v0) / a + (v - v1) / a + (L - d_up - d_down) / v;
}

TEST(PlannerExtraAxes, RotaryAxisStartingAtAJunctionIsACorner) {
  // X 100, then X 100 more while A turns 1 deg per mm; F600 = 10 mm/s, G64 BRISK. At the
  // junction A's velocity jumps from 0 to v·1: the overload rule allows a jump of at most
  // 600·(1.2 - 1)·0.004 = 0.48 deg/s, so the path passes the junction at vj = 0.48 mm/s.
  // Block 1: 0 -> 10 -> vj at 5000; block 2 (a_t = 600/1): vj -> 10 -> 0 at 600.
  const double vj = 600 * 0.2 * 0.004;
  const double t = plan_time(rotary_profile(), {line(O, Vec3(100, 0, 0), 600, {}, 1),
                                                with_a(line(Vec3(100, 0, 0), Vec3(200, 0, 0), 600, {}, 2), 0, 100)});
  EXPECT_NEAR(t, trapezoid(100, 0, 10, vj, 5000) + trapezoid(100, vj, 10, 0, 600), 1e-9);
}

interp::PathElement positioning(double travel, bool synchronous, int line_no) {
  interp::PathElement e = passive(ElementKind::Positioning, synchronous ? "POS A" : "POSA A");
  e.positioning.push_back({"A", travel, 30.0, 600.0, 0.0, 0.0, synchronous});
  e.source.line = static_cast<uint32_t>(line_no);
  return e;
}

TEST(PlannerExtraAxes, CompressedRunSpreadsTheRotaryRateChangeOverItsSpans) {
  // Two tangent-continuous compressor spans of 10 and 20 mm; A's rate d(A)/ds goes 0.5 -> 1.0
  // deg/mm (Δ = 0.5). Inside a compressed run the control's polynomial spreads that change over
  // L = (10 + 20)/2 = 15 mm when A's tolerance allows it (8·tol/Δ >= 15: tol 1 deg):
  // acceleration v²·Δ/L <= 600 gives v <= sqrt(600·15/0.5) = 94.87 mm/s, jerk v³·Δ/L² <= 6000
  // gives v <= cbrt(6000·15²/0.5) = 139.25 mm/s. Not compressed, the jump rules hold: overload
  // 600·(1.2 - 1)·0.004/0.5 = 0.96 mm/s, transition jerk 6000·0.004²/0.5 = 0.192 mm/s.
  interp::PathElement before = line(O, Vec3(10, 0, 0), 600, {}, 1);
  interp::PathElement after = line(Vec3(10, 0, 0), Vec3(30, 0, 0), 600, {}, 2);
  before.compressed_blocks = after.compressed_blocks = 3;
  ElementDynamics db, da;
  for (ElementDynamics* d : {&db, &da}) {
    d->soft = true;
    d->ipo_cycle = 0.004;
    d->ovl_factor = 1.2;
  }
  db.length = 10;
  da.length = 20;
  db.extra = {ExtraAxisTerm{0, 0.5, 60, 600, 6000, 600, 6000, 1.0}};
  da.extra = {ExtraAxisTerm{0, 1.0, 60, 600, 6000, 600, 6000, 1.0}};
  CurvePoint end_of_before, start_of_after;  // both along +X
  const Junction j{before, db, end_of_before, after, da, start_of_after};
  EXPECT_NEAR(CornerConstraint().max_velocity(j), std::sqrt(600.0 * 15.0 / 0.5), 1e-9);
  EXPECT_NEAR(TransitionJerkConstraint().max_velocity(j), std::cbrt(6000.0 * 15.0 * 15.0 / 0.5), 1e-6);
  // With MD33100 = 0.1 deg the fit may round the change over 8·0.1/0.5 = 1.6 mm only (a parabola
  // over L leaves the kinked course by Δ·L/8): v <= sqrt(600·1.6/0.5), cbrt(6000·1.6²/0.5).
  db.extra[0].compress_tol = da.extra[0].compress_tol = 0.1;
  EXPECT_NEAR(CornerConstraint().max_velocity(j), std::sqrt(600.0 * 1.6 / 0.5), 1e-9);
  EXPECT_NEAR(TransitionJerkConstraint().max_velocity(j), std::cbrt(6000.0 * 1.6 * 1.6 / 0.5), 1e-6);
  // A rotary axis turning round (rate +0.5 -> -0.5, Δ = 1) is spread too, not a velocity jump.
  da.extra[0].tangent = -0.5;
  EXPECT_NEAR(CornerConstraint().max_velocity(j), std::sqrt(600.0 * 0.8 / 1.0), 1e-9);
  da.extra[0].tangent = 1.0;
  before.compressed_blocks = 0;
  EXPECT_NEAR(CornerConstraint().max_velocity(j), 600.0 * 0.2 * 0.004 / 0.5, 1e-12);
  EXPECT_NEAR(TransitionJerkConstraint().max_velocity(j), 6000.0 * 0.004 * 0.004 / 0.5, 1e-12);
}

TEST(PlannerExtraAxes, PositioningMoveIsRestToRest) {
  // 90 deg at 30 deg/s, 600 deg/s²: 90/30 + 30/600 = 3.05 s; 5 deg still reaches 30 deg/s
  // (30²/600 = 1.5 deg < 5): 5/30 + 30/600; 1 deg does not: triangle 2·sqrt(1/600).
  interp::PositioningMove m{"A", 90.0, 30.0, 600.0, 0.0, 0.0, true};
  EXPECT_NEAR(PositioningAxes::move_time(m), 3.05, 1e-12);
  m.travel = 5.0;
  EXPECT_NEAR(PositioningAxes::move_time(m), 5.0 / 30.0 + 0.05, 1e-12);
  m.travel = 1.0;
  EXPECT_NEAR(PositioningAxes::move_time(m), 2.0 * std::sqrt(1.0 / 600.0), 1e-12);
  m.lead_time_s = 0.25;
  EXPECT_NEAR(PositioningAxes::move_time(m), 0.25 + 2.0 * std::sqrt(1.0 / 600.0), 1e-12);
}

TEST(PlannerExtraAxes, SposFromRotationArrivesTurningAndBrakesOntoTheAngle) {
  // Position control takes over at 3000 deg/s (500 rpm); braking at 10800 deg/s² covers
  // 3000²/(2·10800) = 416.67 deg in 3000/10800 s. Half a turn beyond it: 180/3000 s at speed,
  // then the braking: 0.06 + 0.277778 s. Both clocks (planner and interpreter) agree.
  interp::PositioningMove m{"S1", 180.0 + 3000.0 * 3000.0 / (2.0 * 10800.0), 3000.0, 10800.0, 0.0, 0.25, true, 3000.0};
  const double expected = 0.25 + 180.0 / 3000.0 + 3000.0 / 10800.0;
  EXPECT_NEAR(PositioningAxes::move_time(m), expected, 1e-9);
  EXPECT_NEAR(m.lead_time_s + interp::move_to_rest_s(m.travel, m.entry_velocity, m.velocity, m.accel, 0.0), expected, 1e-12);
  // Exactly the braking distance: the braking alone.
  m.travel = 3000.0 * 3000.0 / (2.0 * 10800.0);
  EXPECT_NEAR(interp::move_to_rest_s(m.travel, 3000.0, 3000.0, 10800.0, 0.0), 3000.0 / 10800.0, 1e-12);
  EXPECT_NEAR(PositioningAxes::move_time(m), 0.25 + 3000.0 / 10800.0, 1e-9);
  // Entering slower than the cap with room to speed up: 600 -> 1200 deg/s at 600 deg/s² (1 s,
  // 900 deg), braking 1200 deg in 2 s, 900 deg cruise 0.75 s over 3000 deg.
  EXPECT_NEAR(interp::move_to_rest_s(3000.0, 600.0, 1200.0, 600.0, 0.0), 1.0 + 2.0 + 0.75, 1e-12);
  interp::PositioningMove slow{"A", 3000.0, 1200.0, 600.0, 0.0, 0.0, true, 600.0};
  EXPECT_NEAR(PositioningAxes::move_time(slow), 3.75, 1e-9);
  // No room for the cap: peak u² = (2·600·1000 + 600²)/2 = 780000, (u - 600)/600 + u/600.
  const double u = std::sqrt(780000.0);
  EXPECT_NEAR(interp::move_to_rest_s(1000.0, 600.0, 1200.0, 600.0, 0.0), (u - 600.0) / 600.0 + u / 600.0, 1e-12);
  slow.travel = 1000.0;
  EXPECT_NEAR(PositioningAxes::move_time(slow), (u - 600.0) / 600.0 + u / 600.0, 1e-9);
}

TEST(PlannerExtraAxes, PosWaitsForTheLongerOfPathAndAxis) {
  // Block 1: X 10 at F600 (10/10 + 10/5000 = 1.002 s) with POS A 90 (3.05 s): the block takes 3.05 s.
  const double t = plan_time(plain_profile(), {line(O, Vec3(10, 0, 0), 600, {}, 1), positioning(90, true, 1)});
  EXPECT_NEAR(t, 3.05, 1e-9);
  // A short POS (5 deg, 0.217 s) beside the same path: the path decides.
  const double t2 = plan_time(plain_profile(), {line(O, Vec3(10, 0, 0), 600, {}, 1), positioning(5, true, 1)});
  EXPECT_NEAR(t2, 1.002, 1e-9);
}

TEST(PlannerExtraAxes, PosaRunsOnUntilWaitp) {
  // POSA A 90 (3.05 s) in block 1, then X 10 (1.002 s) in block 2, WAITP(A) in block 3.
  interp::PathElement wait = passive(ElementKind::AxisWait, "WAIT A");
  wait.wait_axes = {"A"};
  const double t = plan_time(plain_profile(), {positioning(90, false, 1), line(O, Vec3(10, 0, 0), 600, {}, 2), wait});
  EXPECT_NEAR(t, 3.05, 1e-9);
}

}  // namespace
}  // namespace drycut::motion::testing
