#pragma once
// Sine and cosine of an angle programmed in degrees (AROT Z90, AP=90, ANG=...). Where they are
// 0, ±1/2 or ±1 (multiples of 30°) they are taken exactly: std::cos(π/2) is 6.1e-17, and a frame
// turned by 90° would otherwise leave crumbs like -6.1e-16 in coordinates that are 0 (which flip
// the sign tests and equality tests of a program: IF $P_EP[Y]<0). Elsewhere the library's.
#include <cmath>
#include <numbers>

namespace drycut::geometry {

struct SinCos {
  double sin, cos;
};

inline SinCos sin_cos_degrees(double degrees) {
  double r = std::fmod(degrees, 360.0);
  if (r < 0) r += 360.0;
  if (r == std::trunc(r) && static_cast<int>(r) % 30 == 0) {
    const double h = std::sqrt(3.0) / 2;  // sin 60°
    constexpr double kHalf = 0.5;
    const double sines[12] = {0, kHalf, h, 1, h, kHalf, 0, -kHalf, -h, -1, -h, -kHalf};
    const int k = static_cast<int>(r) / 30 % 12;  // r is 360 for a tiny negative angle
    return {sines[k], sines[(k + 3) % 12]};  // cos φ = sin(φ + 90°)
  }
  const double a = degrees * std::numbers::pi / 180.0;
  return {std::sin(a), std::cos(a)};
}

}  // namespace drycut::geometry
