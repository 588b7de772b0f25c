#include "interp/rest_to_rest.hpp"

#include <algorithm>
#include <cmath>

namespace drycut::interp {

// Rest-to-rest time over a distance d at velocity v, acceleration a and jerk j (j <= 0: none):
// each ramp from 0 to a speed u takes u/a + a/j (with a constant-acceleration phase, u·j >= a²)
// or 2·sqrt(u/j) (jerk only) at an average speed u/2, so up and down cover u·ramp(u).
// Long enough: d/v + ramp(v). Else the peak u solves d = u·ramp(u): u = cbrt(d²·j/4) jerk only,
// or u²/a + u·a/j = d with the acceleration phase; the time is 2·ramp(u).
double rest_to_rest_s(double d, double v, double a, double j) {
  if (d <= 0 || v <= 0 || a <= 0) return 0.0;
  const bool jerk = j > 0 && std::isfinite(j);
  const auto ramp = [&](double u) { return !jerk ? u / a : u * j >= a * a ? u / a + a / j : 2.0 * std::sqrt(u / j); };
  if (d >= v * ramp(v)) return d / v + ramp(v);
  double u = jerk ? std::cbrt(d * d * j / 4.0) : std::sqrt(d * a);
  if (jerk && u * j >= a * a) {
    const double b = a / j;
    u = 0.5 * a * (std::sqrt(b * b + 4.0 * d / a) - b);
  }
  return 2.0 * ramp(u);
}

// From v0 the move rises to a peak u (at most v), cruises, and brakes to 0: rising covers
// (u² - v0²)/(2a), braking u²/(2a). With d beyond both at u = v the cruise takes the rest;
// otherwise u² = (2ad + v0²)/2 (no cruise), and the time is (u - v0)/a + u/a.
double move_to_rest_s(double d, double v0, double v, double a, double j) {
  if (!(v0 > 0)) return rest_to_rest_s(d, v, a, j);
  if (!(a > 0)) return d > 0 ? d / v0 : 0.0;
  const double top = std::max(v, v0);
  const double braking = v0 * v0 / (2.0 * a);
  if (!(d > braking)) return v0 / a;
  const double ramps = (2.0 * top * top - v0 * v0) / (2.0 * a);
  if (d >= ramps) return (top - v0) / a + top / a + (d - ramps) / top;
  const double u = std::sqrt((2.0 * a * d + v0 * v0) / 2.0);
  return (u - v0) / a + u / a;
}

double positioning_share(double distance, double v, double a, double duration, double t) {
  if (!(distance > 0) || !(v > 0) || !(a > 0) || !(duration > 0) || t >= duration) return 1.0;
  if (t <= 0) return 0.0;
  // Trapezoid: ramps of v/a (or a triangle with peak sqrt(d·a)), cruise between.
  const double peak = std::min(v, std::sqrt(distance * a));
  const double ramp = peak / a;
  const double cruise = (distance - peak * ramp) / peak;  // 0 for the triangle
  const double total = 2 * ramp + cruise;
  const double tt = t * total / duration;
  double s;
  if (tt <= ramp) s = 0.5 * a * tt * tt;
  else if (tt <= ramp + cruise) s = 0.5 * peak * ramp + peak * (tt - ramp);
  else s = distance - 0.5 * a * (total - tt) * (total - tt);
  return std::clamp(s / distance, 0.0, 1.0);
}

}  // namespace drycut::interp
