// The sweep finds the fewest knots within a tolerance; for a polygon in a circle the answer is
// the sagitta formula n = ceil(pi / acos(1 - tol / r)).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "machine/alarm.hpp"
#include "machine/machine_profile.hpp"
#include "workload/sweep.hpp"

namespace drycut::workload {
namespace {

TEST(Sweep, LinearOnACircleMatchesTheSagittaFormula) {
  const CurveSource circle = polar_curve([](double) { return 10.0; });
  for (double tol : {0.05, 0.2}) {
    SweepOptions options;
    options.tolerance_mm = tol;
    options.sample_step_mm = 0.02;
    const SweepResult r = sweep_method(circle, Method::Linear, options, machine::default_profile(), nullptr);
    const int expected = static_cast<int>(std::ceil(std::numbers::pi / std::acos(1.0 - tol / 10.0)));
    ASSERT_TRUE(r.found);
    EXPECT_EQ(r.knots, expected) << tol;
    EXPECT_LE(r.max_deviation_mm, tol);
    EXPECT_NEAR(r.max_deviation_mm, 10.0 * (1 - std::cos(std::numbers::pi / expected)), 1e-4);
    EXPECT_TRUE(r.monotone);
    EXPECT_NEAR(r.spacing_mm, 2 * std::numbers::pi * 10 / expected, 1e-6);
    EXPECT_GT(r.sub_bytes, static_cast<size_t>(3 * expected * 20));  // three loops of G1 blocks
    EXPECT_FALSE(r.time_after_m0_s);  // no predictor given
  }
}

TEST(Sweep, PredictorIsAskedForTheThreeDimensionalProgram) {
  const CurveSource circle = polar_curve([](double) { return 10.0; });
  SweepOptions options;
  options.tolerance_mm = 0.5;
  options.sample_step_mm = 0.05;
  std::filesystem::path asked;
  const SweepResult r = sweep_method(circle, Method::CSpline, options, machine::default_profile(),
                                     [&](const std::filesystem::path& p) {
                                       asked = p;
                                       return std::optional<double>(12.5);
                                     });
  ASSERT_TRUE(r.found);
  EXPECT_EQ(asked.filename(), "SWEEP.MPF");
  EXPECT_EQ(r.time_after_m0_s, 12.5);
  EXPECT_LE(r.max_deviation_mm, 0.5);
  // A cubic spline through 4 knots on a radius-10 circle is far off by more than 0.5 mm? It is
  // at least never worse than the polygon through the same knots.
  EXPECT_LE(r.knots, static_cast<int>(std::ceil(std::numbers::pi / std::acos(1.0 - 0.5 / 10.0))));
}

TEST(Sweep, BadToleranceIsAUsageError) {
  SweepOptions options;
  options.tolerance_mm = 0;
  EXPECT_THROW(sweep_method(polar_curve([](double) { return 10.0; }), Method::Linear, options,
                            machine::default_profile(), nullptr),
               UsageError);
}

}  // namespace
}  // namespace drycut::workload
