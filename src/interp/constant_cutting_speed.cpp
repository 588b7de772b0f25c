#include "interp/constant_cutting_speed.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace drycut::interp {
namespace {

// ∫_{a}^{b} dr / n(r) for 0 <= a <= b.
double inverse_speed_integral(double speed_mm_min, double a, double b, double min_rpm, double max_rpm) {
  const double two_pi = 2.0 * std::numbers::pi;
  const double r_max = speed_mm_min / (two_pi * max_rpm);  // inside: n_max
  const double r_min = min_rpm > 0 ? speed_mm_min / (two_pi * min_rpm) : INFINITY;  // beyond: n_min
  double sum = 0.0;
  // Inside r_max.
  if (a < r_max) sum += (std::min(b, r_max) - a) / max_rpm;
  // Between: 1/n = 2π r / Vc.
  const double lo = std::max(a, r_max), hi = std::min(b, r_min);
  if (hi > lo) sum += two_pi * (hi * hi - lo * lo) / (2.0 * speed_mm_min);
  // Beyond r_min.
  if (b > r_min) sum += (b - std::max(a, r_min)) / min_rpm;
  return sum;
}

}  // namespace

double constant_cutting_speed_rpm(double speed_mm_min, double x0, double x1, double min_rpm, double max_rpm) {
  const auto at = [&](double x) {
    const double r = std::abs(x);
    double n = r > 0 ? speed_mm_min / (2.0 * std::numbers::pi * r) : max_rpm;
    n = std::min(n, max_rpm);
    return min_rpm > 0 ? std::max(n, min_rpm) : n;
  };
  if (speed_mm_min <= 0) return 0.0;
  if (min_rpm > 0 && min_rpm >= max_rpm) return min_rpm;  // G25 above the limits: it holds throughout
  if (x0 == x1) return at(x0);
  double integral = 0.0;
  if ((x0 >= 0) == (x1 >= 0)) {
    const double a = std::min(std::abs(x0), std::abs(x1)), b = std::max(std::abs(x0), std::abs(x1));
    integral = inverse_speed_integral(speed_mm_min, a, b, min_rpm, max_rpm);
  } else {  // across the centre
    integral = inverse_speed_integral(speed_mm_min, 0.0, std::abs(x0), min_rpm, max_rpm) +
               inverse_speed_integral(speed_mm_min, 0.0, std::abs(x1), min_rpm, max_rpm);
  }
  return integral > 0 ? std::abs(x1 - x0) / integral : at(x0);
}

}  // namespace drycut::interp
