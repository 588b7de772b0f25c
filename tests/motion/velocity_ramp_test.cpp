// Closed-form ramps: hand-derived times and distances, reach as the inverse of distance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "motion/velocity_ramp.hpp"

namespace drycut::motion {
namespace {

TEST(VelocityRamp, BriskIsConstantAcceleration) {
  RampLimits l{5000, kNoJerkLimit};
  EXPECT_DOUBLE_EQ(ramp_time(0, 100, l), 0.02);
  EXPECT_DOUBLE_EQ(ramp_distance(0, 100, l), 1.0);  // v²/2a
  EXPECT_DOUBLE_EQ(ramp_reach(0, 1.0, l), 100.0);
  EXPECT_DOUBLE_EQ(ramp_reach(30, 2.0, l), std::sqrt(900.0 + 20000.0));
}

TEST(VelocityRamp, SoftWithConstantAccelerationPhase) {
  // a = 1000, j = 40000: Δv = 100 >= a²/j = 25, T = Δv/a + a/j = 0.1 + 0.025.
  RampLimits l{1000, 40000};
  EXPECT_NEAR(ramp_time(0, 100, l), 0.125, 1e-15);
  EXPECT_NEAR(ramp_distance(20, 120, l), 70.0 * 0.125, 1e-12);
}

TEST(VelocityRamp, SoftWithoutConstantAccelerationPhase) {
  // Δv = 10 < a²/j = 625: T = 2·sqrt(Δv/j).
  RampLimits l{5000, 40000};
  EXPECT_NEAR(ramp_time(50, 40, l), 2.0 * std::sqrt(10.0 / 40000.0), 1e-15);
}

TEST(VelocityRamp, ReachInvertsDistance) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> v(0, 800), d(1e-6, 200), a(100, 20000), j(1000, 1e6);
  for (int i = 0; i < 20000; ++i) {
    RampLimits l{a(rng), (i % 3 == 0) ? kNoJerkLimit : j(rng)};
    const double v0 = v(rng), dist = d(rng);
    const double v1 = ramp_reach(v0, dist, l);
    ASSERT_GE(v1, v0);
    ASSERT_NEAR(ramp_distance(v0, v1, l), dist, 1e-7 * (1 + dist)) << v0 << " " << dist;
  }
}

TEST(VelocityRamp, ReachUpperBoundIsAboveTheReachAndTightForShortSteps) {
  // The bound the passes use to skip a ramp: never below ramp_reach (the distance of a ramp to
  // it, computed independently by ramp_distance, covers the given distance), equal to it under
  // BRISK, and within 10 % of the gain for a short step at speed under SOFT.
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  for (int i = 0; i < 20000; ++i) {
    const RampLimits l{100 + 5000 * u01(rng), u01(rng) < 0.2 ? kNoJerkLimit : 1000 + 200000 * u01(rng)};
    const double v0 = u01(rng) < 0.1 ? 0.0 : 200 * u01(rng);
    const double d = 1e-4 + 20 * u01(rng) * u01(rng);
    const double bound = reach_upper_bound(v0, d, l);
    const double reach = ramp_reach(v0, d, l);
    ASSERT_GE(bound, reach) << v0 << " " << d << " " << l.accel << " " << l.jerk;
    ASSERT_GE(ramp_distance(v0, bound, l), d * (1 - 1e-9));
    if (!std::isfinite(l.jerk)) {
      ASSERT_NEAR(bound, reach, 1e-9 * reach);
    }
  }
  const RampLimits soft{2000, 50000};
  const double v0 = 50, d = 0.05;  // a 0.05 mm step at 50 mm/s
  EXPECT_LT(reach_upper_bound(v0, d, soft) - v0, 1.1 * (ramp_reach(v0, d, soft) - v0) + 1e-9);
}

TEST(VelocityRamp, SegmentReachesCapAndCruises) {
  // BRISK, 0 -> 100 -> 0 over 10 mm at a = 5000: ramps of 1 mm each, cruise 8 mm.
  SegmentProfile p = plan_segment(0, 0, 100, 10, {5000, kNoJerkLimit});
  EXPECT_DOUBLE_EQ(p.peak, 100);
  EXPECT_NEAR(p.duration, 10.0 / 100.0 + 100.0 / 5000.0, 1e-12);
  ProfileState end = evaluate(p, p.duration);
  EXPECT_NEAR(end.s, 10.0, 1e-9);
  EXPECT_NEAR(end.v, 0.0, 1e-9);
  ProfileState mid = evaluate(p, p.duration / 2);
  EXPECT_NEAR(mid.s, 5.0, 1e-9);
  EXPECT_NEAR(mid.v, 100.0, 1e-9);
}

TEST(VelocityRamp, TriangleWhenTooShortForCap) {
  // BRISK: peak² = a·L (from rest to rest) -> peak = sqrt(5000·0.5) = 50, time = 2·peak/a.
  SegmentProfile p = plan_segment(0, 0, 1000, 0.5, {5000, kNoJerkLimit});
  EXPECT_NEAR(p.peak, 50.0, 1e-9);
  EXPECT_NEAR(p.duration, 0.02, 1e-12);
}

TEST(VelocityRamp, SoftSegmentEndsAtItsLength) {
  RampLimits l{5000, 40000};
  SegmentProfile p = plan_segment(10, 30, 500, 3.0, l);
  ProfileState end = evaluate(p, p.duration);
  EXPECT_NEAR(end.s, 3.0, 1e-9);
  EXPECT_NEAR(end.v, 30.0, 1e-6);
  EXPECT_NEAR(end.a, 0.0, 1e-6);
  // The peak satisfies the distance equation exactly.
  EXPECT_NEAR(ramp_distance(10, p.peak, l) + ramp_distance(p.peak, 30, l), 3.0, 1e-9);
}

TEST(VelocityRamp, SoftSegmentPeakMatchesABisectionOfTheDistanceEquation) {
  // Reference: plain bisection of D(v0, p) + D(p, v1) = L on [max(v0, v1), cap], in both the
  // jerk-only regime (Δv < a²/j = 625) and at full acceleration, equal and unequal ends, a
  // peak just above the higher end and one near the cap.
  const RampLimits l{5000, 40000};
  auto needed = [&](double v0, double v1, double p) { return ramp_distance(v0, p, l) + ramp_distance(p, v1, l); };
  for (double v0 : {0.0, 3.0, 25.0, 400.0}) {
    for (double v1 : {0.0, 3.0, 25.0, 400.0}) {
      const double vhigh = std::max(v0, v1), cap = 2000.0;
      for (double fraction : {1e-9, 1e-4, 0.01, 0.3, 0.9}) {
        // A length between the ramp v0 -> v1 alone and the ramps through the cap.
        const double lo_len = needed(v0, v1, vhigh), hi_len = needed(v0, v1, cap);
        const double length = lo_len + fraction * (hi_len - lo_len);
        double lo = vhigh, hi = cap;
        for (int i = 0; i < 200; ++i) (needed(v0, v1, 0.5 * (lo + hi)) <= length ? lo : hi) = 0.5 * (lo + hi);
        const SegmentProfile p = plan_segment(v0, v1, cap, length, l);
        SCOPED_TRACE(testing::Message() << "v0 " << v0 << " v1 " << v1 << " fraction " << fraction);
        EXPECT_NEAR(p.peak, lo, 1e-9 * lo + 1e-12);
        EXPECT_LE(needed(v0, v1, p.peak), length * (1 + 1e-12));
        EXPECT_NEAR(evaluate(p, p.duration).s, length, 1e-9 * length + 1e-15);
      }
    }
  }
  // A ramp that fills the segment exactly: the peak is the higher end.
  const double length = ramp_distance(3.0, 25.0, l);
  EXPECT_DOUBLE_EQ(plan_segment(3.0, 25.0, 2000.0, length, l).peak, 25.0);
}

TEST(VelocityRamp, ShortSegmentOfALongRampUsesConstantAcceleration) {
  // 0 -> 10 over 0.01 mm cannot be done with zero-acceleration ends at j = 40000.
  SegmentProfile p = plan_segment(0, 10, 100, 0.01, {5000, 40000});
  EXPECT_EQ(p.phase_count, 1);
  EXPECT_NEAR(p.duration, 2 * 0.01 / 10.0, 1e-15);
  EXPECT_NEAR(p.phases[0].accel_start, 100.0 / 0.02, 1e-9);
}

}  // namespace
}  // namespace drycut::motion
