#pragma once
// A cube root for the planner's hot path. std::cbrt costs a frexp/ldexp pair per call and was
// ~13 % of `drycut run` on short-segment programs (callgrind); this starts from a bit-level guess
// (the exponent divided by three, as fdlibm does) and refines with Halley's method, whose cubic
// convergence reaches double precision (a few ulps) in three steps from the guess's ~5 % error.
#include <cmath>
#include <cstdint>
#include <cstring>

namespace drycut::motion {

inline double cube_root(double x) {
  if (!(x > 0.0) || !std::isfinite(x) || x < 1e-300) return std::cbrt(x);  // zero, sign, NaN, inf, denormals
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  bits = bits / 3 + 0x2a9f7893782da1ceULL;
  double y;
  std::memcpy(&y, &bits, sizeof y);
  for (int i = 0; i < 3; ++i) {
    const double y3 = y * y * y;
    y *= (y3 + 2.0 * x) / (2.0 * y3 + x);
  }
  return y;
}

}  // namespace drycut::motion
