// The planner on smoothed corners (interp/corner_smoothing.hpp -> Planner): a square under G642
// is faster than under G64, its corner feed is the rounding's centripetal limit computed here
// from the Bezier by hand, and G641 on a too-short block plans exactly as G64.
#include <gtest/gtest.h>

#include <cmath>

#include "../interp/interp_test_support.hpp"
#include "interp/corner_smoothing.hpp"
#include "motion/planner.hpp"
#include "planner_test_support.hpp"

namespace drycut::motion::testing {
namespace {

struct SmoothedPlan {
  Recorder rec;
  PlanSummary summary;
};

std::unique_ptr<SmoothedPlan> plan_program(const std::string& text, const machine::MachineProfile& profile) {
  auto run = interp::testing::run_program(text, profile);
  EXPECT_FALSE(run->alarm) << run->alarm->format();
  auto out = std::make_unique<SmoothedPlan>();
  Planner planner(profile, out->rec);
  interp::CornerSmoothing stage(planner, profile);
  for (auto& e : run->sink.elements) stage.consume(interp::PathElement(e));
  stage.finish();
  out->summary = planner.summary();
  return out;
}

machine::MachineProfile square_profile() {
  machine::MachineProfile p = interp::testing::test_profile();
  p.ipo_cycle_s = 0.004;
  p.max_accel_ovl_factor = 1.2;
  p.curv_effect_on_path_accel = 0.75;
  p.short_block_factor = 0.9;
  p.lookahead_blocks = 64;
  p.path_jerk_mm_s3 = 40000;
  p.smoothing.mode = 11;  // contour tolerance SD42465
  p.smoothing.contur_tol_mm = 0.1;
  return p;
}

const std::string kSquare = "G0 X0 Y0 Z0\nF6000\nG1 X20\nY20\nX0\nY0\nM30\n";

// The G642 rounding of the corner (20, 0) from +X to +Y with d = 4 * 0.1 / sqrt(2) (quadratic
// Bezier P0, C, P2): per axis the centripetal limit sqrt(share * a / |kappa_i|), minimised over a
// dense sampling.
double centripetal_limit_by_hand(double share, double accel) {
  const double d = 0.4 / std::sqrt(2.0);
  const Vec3 c(20, 0, 0), p0 = c - d * Vec3::UnitX(), p2 = c + d * Vec3::UnitY();
  double v = 1e300;
  for (int k = 0; k <= 20000; ++k) {
    const double t = k / 20000.0;
    const Vec3 d1 = 2 * (1 - t) * (c - p0) + 2 * t * (p2 - c);
    const Vec3 d2 = 2 * (p0 - 2 * c + p2);
    const Vec3 tangent = d1.normalized();
    const Vec3 kappa = (d2 - d2.dot(tangent) * tangent) / d1.squaredNorm();
    for (int i = 0; i < 2; ++i)
      if (std::abs(kappa[i]) > 1e-12) v = std::min(v, std::sqrt(share * accel / std::abs(kappa[i])));
  }
  return v;
}

TEST(CornerSmoothingPlanner, SquareUnderG642IsFasterAndItsCornerFeedIsTheCentripetalLimit) {
  const auto p = square_profile();
  const auto g64 = plan_program("G64 " + kSquare, p);
  const auto g642 = plan_program("G642 " + kSquare, p);
  // Each corner: G64 brakes to 4 mm/s, the rounding runs at about 31 mm/s (2.5 ms saved each).
  EXPECT_LT(g642->summary.time_s, g64->summary.time_s - 0.005);
  // G64: the 90-degree corner at the end of X20 (line 3) allows 5000 * 0.2 * 0.004 / 1 = 4 mm/s.
  for (const auto& b : g64->rec.blocks)
    if (b.source.line == 3) {
      EXPECT_NEAR(b.v_min_mm_s, 4.0, 1e-9);
    }
  size_t rounded = 0;
  const double expected = centripetal_limit_by_hand(0.75, 5000);
  for (const auto& b : g642->rec.blocks) {
    if (b.smoothing_deviation_mm < 0) continue;
    ++rounded;
    EXPECT_EQ(b.label, "G642");
    EXPECT_NEAR(b.smoothing_deviation_mm, 0.1, 1e-12);
    EXPECT_EQ(b.limit, Limit::Curvature);
    EXPECT_NEAR(b.v_min_mm_s, expected, 0.01 * expected) << "line " << b.source.line;
    EXPECT_GT(b.v_min_mm_s, 4.0 * 5);  // far above the G64 corner
  }
  EXPECT_EQ(rounded, 3u);
}

TEST(CornerSmoothingPlanner, SoftSquareUnderG642IsFasterThanG64OnTheDefaultMachine) {
  // The embedded machine (axis jerk 100 m/s³, MD33100 0.1 mm): G64 brakes each corner to 4 mm/s
  // along S-curves; the rounding runs at about 20 mm/s, held by the curvature jerk. (With half
  // the axis jerk and a 0.1 mm contour tolerance the rounding is not faster: not asserted.)
  const auto p = machine::default_profile();
  const auto g64 = plan_program("SOFT\nG64 " + kSquare, p);
  const auto g642 = plan_program("SOFT\nG642 " + kSquare, p);
  EXPECT_LT(g642->summary.time_s, g64->summary.time_s - 0.005);
}

TEST(CornerSmoothingPlanner, G641OnATooShortBlockPlansAsG64) {
  const auto p = square_profile();
  const std::string program = "G0 X0 Y0 Z0\nF6000\nG1 X20\nY1\nX0\nM30\n";
  const auto g64 = plan_program("G64 " + program, p);
  const auto g641 = plan_program("G641 ADIS=2 " + program, p);  // half of the 1 mm block: 75 % short
  EXPECT_EQ(g641->rec.blocks.size(), g64->rec.blocks.size());
  EXPECT_DOUBLE_EQ(g641->summary.time_s, g64->summary.time_s);
  const auto fits = plan_program("G641 ADIS=0.4 " + program, p);  // 0.4 of 0.5 mm: rounded
  EXPECT_EQ(fits->rec.blocks.size(), g64->rec.blocks.size() + 2);
  EXPECT_LT(fits->summary.time_s, g64->summary.time_s);
}

}  // namespace
}  // namespace drycut::motion::testing
