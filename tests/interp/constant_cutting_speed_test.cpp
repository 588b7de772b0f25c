// G96 along one move (constant_cutting_speed.hpp): the closed form against an independent
// numeric integral of the time, and the cases written out by hand.
#include "interp/constant_cutting_speed.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace drycut::interp {
namespace {

// The equal-time speed by brute force: midpoint rule over x with 200000 steps.
double numeric_rpm(double vc, double x0, double x1, double n_min, double n_max) {
  constexpr int kSteps = 200000;
  const double h = (x1 - x0) / kSteps;
  double minutes_per_mm = 0.0;
  for (int k = 0; k < kSteps; ++k) {
    const double r = std::abs(x0 + (k + 0.5) * h);
    double n = r > 0 ? vc / (2 * std::numbers::pi * r) : n_max;
    n = std::clamp(n, n_min, n_max);
    minutes_per_mm += std::abs(h) / n;
  }
  return std::abs(x1 - x0) / minutes_per_mm;
}

TEST(ConstantCuttingSpeed, MatchesTheNumericIntegralOfTheTime) {
  struct Case {
    double vc, x0, x1, n_min, n_max;
  };
  // Facing to the centre under LIMS, outward, across the centre, with a G25 floor, all inside
  // one limit, a taper that starts inside LIMS.
  const Case cases[] = {{180000, 50, 0, 0, 2500},  {180000, 0, 50, 0, 2500},   {150000, 30, -20, 0, 3000},
                        {200000, 10, 120, 400, 4000}, {100000, 40, 45, 0, 5000}, {250000, 5, 60, 0, 1800}};
  for (const Case& c : cases) {
    const double closed = constant_cutting_speed_rpm(c.vc, c.x0, c.x1, c.n_min, c.n_max);
    EXPECT_NEAR(closed, numeric_rpm(c.vc, c.x0, c.x1, c.n_min, c.n_max), closed * 1e-6)
        << c.x0 << " -> " << c.x1;
  }
}

TEST(ConstantCuttingSpeed, HandCases) {
  // No change of diameter: n at that diameter (Vc / (π·D)), or the limit.
  EXPECT_DOUBLE_EQ(constant_cutting_speed_rpm(200000, 20, 20, 0, 5000), 200000 / (40 * std::numbers::pi));
  EXPECT_DOUBLE_EQ(constant_cutting_speed_rpm(200000, 0, 0, 0, 2500), 2500);
  // Entirely above LIMS's radius: the limit throughout.
  EXPECT_DOUBLE_EQ(constant_cutting_speed_rpm(100000, 1, 5, 0, 1000), 1000);
  // 20 -> 30 without limits: ∫ dr/n = 2π(30² − 20²)/(2·200000) min per 10 mm.
  EXPECT_NEAR(constant_cutting_speed_rpm(200000, 20, 30, 0, 1e9), 10 / (std::numbers::pi * 500 / 200000), 1e-9);
}

}  // namespace
}  // namespace drycut::interp
