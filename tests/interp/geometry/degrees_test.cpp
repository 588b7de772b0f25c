// sin_cos_degrees: exact at multiples of 30° (the values 0, ±1/2, ±1 and ±√3/2 as sqrt(3)/2),
// the library's values elsewhere, for any sign and number of turns.
#include "interp/geometry/degrees.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace drycut::geometry {
namespace {

TEST(Degrees, QuarterTurnsAndTwelfthsAreExact) {
  const double h = std::sqrt(3.0) / 2;
  struct Case { double deg, sin, cos; };
  const Case cases[] = {{0, 0, 1},       {30, 0.5, h},    {60, h, 0.5},    {90, 1, 0},      {120, h, -0.5},
                        {150, 0.5, -h},  {180, 0, -1},    {210, -0.5, -h}, {240, -h, -0.5}, {270, -1, 0},
                        {300, -h, 0.5},  {330, -0.5, h},  {-90, -1, 0},    {450, 1, 0},     {-270, 1, 0},
                        {720, 0, 1},     {-180, 0, -1},   {-1e-14, 0, 1}};  // fmod + 360 rounds to 360
  for (const auto& c : cases) {
    const SinCos sc = sin_cos_degrees(c.deg);
    EXPECT_EQ(sc.sin, c.sin) << c.deg;
    EXPECT_EQ(sc.cos, c.cos) << c.deg;
  }
}

TEST(Degrees, OtherAnglesAreTheLibrarys) {
  for (const double deg : {1.0, 45.0, 89.999, 90.001, -33.3, 1234.5}) {
    const double a = deg * std::numbers::pi / 180;
    const SinCos sc = sin_cos_degrees(deg);
    EXPECT_EQ(sc.sin, std::sin(a)) << deg;
    EXPECT_EQ(sc.cos, std::cos(a)) << deg;
  }
}

}  // namespace
}  // namespace drycut::geometry
