#include "report/svg_axis_ticks.hpp"

#include <cmath>
#include <cstdio>

namespace drycut::report {

double nice_tick_step(double lo, double hi, int target) {
  const double span = hi - lo;
  if (!std::isfinite(span) || span <= 0 || target < 1) return 1.0;
  const double raw = span / target;
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  const double fraction = raw / magnitude;
  // Round the raw step to the nearest of 1, 2, 5, 10 (geometric midpoints).
  const double nice = fraction < std::sqrt(2.0) ? 1 : fraction < std::sqrt(10.0) ? 2 : fraction < std::sqrt(50.0) ? 5 : 10;
  return nice * magnitude;
}

std::vector<double> nice_ticks(double lo, double hi, int target) {
  std::vector<double> ticks;
  if (!std::isfinite(lo) || !std::isfinite(hi) || hi < lo) return ticks;
  const double step = nice_tick_step(lo, hi, target);
  const double eps = step * 1e-9;
  for (double k = std::ceil((lo - eps) / step); k * step <= hi + eps && ticks.size() < 1000; k += 1) {
    const double v = k * step;
    ticks.push_back(std::abs(v) < eps ? 0.0 : v);
  }
  return ticks;
}

std::string format_tick(double value, double step) {
  int decimals = 0;
  if (step > 0 && std::isfinite(step)) {
    // Enough decimals that consecutive ticks differ in their labels.
    decimals = std::max(0, static_cast<int>(std::ceil(-std::log10(step) - 1e-9)));
    decimals = std::min(decimals, 9);
  }
  if (std::abs(value) < step * 1e-9) value = 0.0;  // no "-0"
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, value);
  return buf;
}

}  // namespace drycut::report
