// Invariants over seeded random polylines, and bounded memory over a long program.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "motion/planner.hpp"
#include "planner_test_support.hpp"

namespace drycut::motion::testing {
namespace {

// Checks every sample against the axis limits as it arrives (no sample storage).
struct LimitChecker : PlanObserver {
  Vec3 vmax, amax;
  double feed_cap = 0;  // highest programmed F of the run (mm/s)
  size_t samples = 0;
  double worst_v = 0, worst_a = 0;  // largest ratio to the limit seen
  Vec3 last_position;
  bool has_last = false;
  double max_step = 0;  // largest distance between consecutive samples
  void on_sample(const TrajectorySample& s) override {
    ++samples;
    for (int i = 0; i < 3; ++i) {
      worst_v = std::max(worst_v, std::abs(s.axis_velocity_mm_s[i]) / vmax[i]);
      worst_a = std::max(worst_a, std::abs(s.axis_accel_mm_s2[i]) / amax[i]);
    }
    if (has_last) max_step = std::max(max_step, (s.position - last_position).norm());
    last_position = s.position;
    has_last = true;
  }
};

TEST(PlannerProperty, RandomPolylinesRespectAxisVelocityAndAcceleration) {
  std::mt19937 rng(20240611);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), u01(0.0, 1.0);
  size_t total_samples = 0;
  double worst_v = 0, worst_a = 0;
  for (int run = 0; run < 300; ++run) {
    auto profile = plain_profile(1 + static_cast<int>(u01(rng) * 20));
    // Axes with different limits so that projections matter.
    for (auto& a : profile.axes) {
      a.max_velocity_mm_s = 100 + 600 * u01(rng);
      a.max_accel_mm_s2 = 500 + 5000 * u01(rng);
      a.max_jerk_mm_s3 = 5000 + 100000 * u01(rng);
    }
    profile.path_jerk_mm_s3 = 5000 + 100000 * u01(rng);
    profile.max_accel_ovl_factor = 1.0 + 0.5 * u01(rng);
    LimitChecker check;
    for (int i = 0; i < 3; ++i) {
      check.vmax[i] = profile.axes[static_cast<size_t>(i)].max_velocity_mm_s;
      check.amax[i] = profile.axes[static_cast<size_t>(i)].max_accel_mm_s2;
    }
    PlannerOptions options;
    options.emit_samples = true;
    Planner planner(profile, check, options);
    const bool soft = u01(rng) < 0.5;
    const int points = 2 + static_cast<int>(u01(rng) * 40);
    Vec3 p = Vec3::Zero();
    double min_time = 0;
    for (int k = 0; k < points; ++k) {
      // Lengths from 0.01 mm to 50 mm (log-uniform), sometimes straight on.
      const double len = std::pow(10.0, -2.0 + 3.7 * u01(rng));
      Vec3 dir(unit(rng), unit(rng), unit(rng));
      if (dir.norm() < 1e-3) dir = Vec3::UnitX();
      Vec3 q = p + dir.normalized() * len;
      const double feed = 60.0 * (5 + 900 * u01(rng));
      Mode mode{.soft = soft, .exact_stop = u01(rng) < 0.2};
      if (u01(rng) < 0.1) {
        planner.consume(rapid(p, q));
      } else {
        planner.consume(line(p, q, feed, mode));
        min_time += len / (feed / 60.0);
      }
      p = q;
    }
    planner.finish();
    ASSERT_GT(check.samples, 0u);
    total_samples += check.samples;
    worst_v = std::max(worst_v, check.worst_v);
    worst_a = std::max(worst_a, check.worst_a);
    EXPECT_LE(check.worst_v, 1.0 + 1e-6) << "run " << run;
    EXPECT_LE(check.worst_a, 1.0 + 1e-6) << "run " << run;
    // Never faster than programmed: the time is at least the sum of L/F.
    EXPECT_GE(planner.summary().time_s, min_time * (1 - 1e-9)) << "run " << run;
    // Consecutive samples are no farther apart than the fastest axis-projected speed allows.
    EXPECT_LE(check.max_step, check.vmax.norm() * profile.ipo_cycle_s * (1 + 1e-6)) << "run " << run;
    // The last sample lies on the path end within one IPO step.
    EXPECT_LE((check.last_position - p).norm(), check.vmax.norm() * profile.ipo_cycle_s + 1e-9);
  }
  // The limits are actually reached somewhere (the test would be vacuous otherwise).
  EXPECT_GT(worst_v, 0.99);
  EXPECT_GT(worst_a, 0.99);
  EXPECT_GT(total_samples, 10000u);
  std::printf("samples %zu, worst axis velocity ratio %.9f, acceleration ratio %.9f\n", total_samples, worst_v, worst_a);
}

TEST(PlannerProperty, LongProgramRunsInABoundedWindow) {
  // 100 000 short zig-zag blocks; the window never holds more than the look-ahead depth.
  auto profile = plain_profile(64);
  struct Counter : PlanObserver {
    size_t blocks = 0;
    void on_block(const BlockTiming&) override { ++blocks; }
  } counter;
  Planner planner(profile, counter);
  Vec3 p = Vec3::Zero();
  size_t peak = 0;
  for (int i = 0; i < 100000; ++i) {
    Vec3 q = p + Vec3(0.1, (i % 2 == 0) ? 0.01 : -0.01, 0);
    planner.consume(line(p, q, 3000, Mode{.soft = true}));
    p = q;
    peak = std::max(peak, planner.window_nodes());
  }
  planner.finish();
  EXPECT_EQ(counter.blocks, 100000u);
  // One node per line plus the committed front node; the window holds 65 elements at most
  // between the append and the commit.
  EXPECT_LE(peak, 66u);
  EXPECT_LE(planner.peak_window_nodes(), 66u);
  EXPECT_LE(planner.peak_window_elements(), 65u);
  EXPECT_EQ(planner.window_nodes(), 0u);
  EXPECT_GT(planner.summary().time_s, planner.summary().path_length_mm / 50.0);
}

}  // namespace
}  // namespace drycut::motion::testing

namespace drycut::motion::testing {
namespace {

TEST(PlannerProperty, ArcsStayNearTheAxisLimitsBetweenNodes) {
  // On curves the limits hold at the nodes; between them (h <= v·T_IPO) the tangent turns
  // by at most h/r, so velocity and acceleration may exceed by a small relative amount.
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  double worst_v = 0, worst_a = 0;
  for (int run = 0; run < 100; ++run) {
    auto profile = plain_profile();
    LimitChecker check;
    for (int i = 0; i < 3; ++i) {
      check.vmax[i] = profile.axes[static_cast<size_t>(i)].max_velocity_mm_s;
      check.amax[i] = profile.axes[static_cast<size_t>(i)].max_accel_mm_s2;
    }
    PlannerOptions options;
    options.emit_samples = true;
    Planner planner(profile, check, options);
    const double r = 0.5 + 50 * u01(rng);
    const double sweep = (u01(rng) < 0.5 ? -1 : 1) * (0.2 + 6 * u01(rng));
    auto arc = std::make_shared<TestArc>(Vec3::Zero(), r, 6.28 * u01(rng), sweep);
    planner.consume(motion(arc, 60.0 * (20 + 800 * u01(rng)), Mode{.soft = u01(rng) < 0.5}, interp::ElementKind::Arc));
    planner.finish();
    worst_v = std::max(worst_v, check.worst_v);
    worst_a = std::max(worst_a, check.worst_a);
  }
  std::printf("arcs: worst axis velocity ratio %.6f, acceleration ratio %.6f\n", worst_v, worst_a);
  // Guaranteed at nodes only; between them a margin of 2 % is what drycut promises on arcs.
  EXPECT_LE(worst_v, 1.02);
  EXPECT_LE(worst_a, 1.02);
  EXPECT_GT(worst_a, 0.9);  // the centripetal limit was actually reached
}

}  // namespace
}  // namespace drycut::motion::testing
