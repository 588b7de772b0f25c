#include "report/svg_axis_ticks.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace drycut::report {
namespace {

TEST(AxisTicks, StepIsOneTwoOrFiveTimesAPowerOfTen) {
  EXPECT_DOUBLE_EQ(nice_tick_step(0, 10, 5), 2.0);    // raw 2
  EXPECT_DOUBLE_EQ(nice_tick_step(0, 100, 4), 20.0);  // raw 25 -> 20 (25 < sqrt(10)*10)
  EXPECT_DOUBLE_EQ(nice_tick_step(0, 1, 10), 0.1);
  EXPECT_DOUBLE_EQ(nice_tick_step(0, 3000, 6), 500.0);
  EXPECT_DOUBLE_EQ(nice_tick_step(5, 5, 6), 1.0);  // empty range
}

TEST(AxisTicks, TicksLieInsideTheRangeOnMultiplesOfTheStep) {
  const auto t = nice_ticks(-23.4, 23.4, 8);
  ASSERT_FALSE(t.empty());
  const double step = nice_tick_step(-23.4, 23.4, 8);  // raw 5.85 -> 5
  EXPECT_DOUBLE_EQ(step, 5.0);
  EXPECT_DOUBLE_EQ(t.front(), -20.0);
  EXPECT_DOUBLE_EQ(t.back(), 20.0);
  EXPECT_EQ(t.size(), 9u);
  for (double v : t) EXPECT_NEAR(std::remainder(v, step), 0.0, 1e-9);
}

TEST(AxisTicks, InvalidRangeGivesNoTicks) {
  EXPECT_TRUE(nice_ticks(1, 0).empty());
  EXPECT_TRUE(nice_ticks(0, NAN).empty());
}

TEST(AxisTicks, LabelsUseTheDecimalsTheStepNeeds) {
  EXPECT_EQ(format_tick(1500, 500), "1500");
  EXPECT_EQ(format_tick(0.25, 0.05), "0.25");
  EXPECT_EQ(format_tick(-1.5, 0.5), "-1.5");
  EXPECT_EQ(format_tick(-1e-17, 0.1), "0.0");  // no "-0.0"
}

}  // namespace
}  // namespace drycut::report
