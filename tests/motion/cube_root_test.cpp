#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "motion/cube_root.hpp"

namespace drycut::motion {
namespace {

TEST(CubeRoot, ExactCubesAndSpecialValues) {
  EXPECT_DOUBLE_EQ(cube_root(27.0), 3.0);
  EXPECT_DOUBLE_EQ(cube_root(1e-9), 1e-3);
  EXPECT_DOUBLE_EQ(cube_root(8e12), 2e4);
  EXPECT_EQ(cube_root(0.0), 0.0);
  EXPECT_DOUBLE_EQ(cube_root(-8.0), -2.0);
  EXPECT_TRUE(std::isnan(cube_root(std::nan(""))));
  EXPECT_TRUE(std::isinf(cube_root(INFINITY)));
}

TEST(CubeRoot, MatchesTheLibraryToFullPrecisionOverManyDecades) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> exponent(-290.0, 300.0), mantissa(1.0, 10.0);
  for (int i = 0; i < 200000; ++i) {
    const double x = mantissa(rng) * std::pow(10.0, exponent(rng));
    const double y = cube_root(x), ref = std::cbrt(x);
    ASSERT_NEAR(y, ref, 1e-15 * ref) << x;  // a few ulps
  }
}

}  // namespace
}  // namespace drycut::motion
