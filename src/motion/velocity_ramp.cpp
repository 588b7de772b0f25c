#include "motion/velocity_ramp.hpp"

#include <algorithm>
#include <cmath>

#include "motion/cube_root.hpp"

namespace drycut::motion {
namespace {

bool has_jerk_limit(RampLimits l) { return std::isfinite(l.jerk); }

// Appends the phases of a ramp from v0 to v1 (sign from the direction).
void append_ramp(SegmentProfile& p, double v0, double v1, RampLimits l) {
  double dv = std::abs(v1 - v0);
  if (dv <= 0) return;
  double sign = v1 > v0 ? 1.0 : -1.0;
  auto add = [&](double duration, double a0, double jerk) {
    if (duration > 0) p.phases[static_cast<size_t>(p.phase_count++)] = {duration, a0, jerk};
  };
  if (!has_jerk_limit(l)) {
    add(dv / l.accel, sign * l.accel, 0.0);
  } else if (dv >= l.accel * l.accel / l.jerk) {
    double tj = l.accel / l.jerk;
    add(tj, 0.0, sign * l.jerk);
    add(dv / l.accel - tj, sign * l.accel, 0.0);
    add(tj, sign * l.accel, -sign * l.jerk);
  } else {
    double tj = std::sqrt(dv / l.jerk);
    add(tj, 0.0, sign * l.jerk);
    add(tj, sign * l.jerk * tj, -sign * l.jerk);
  }
}

// Distance of the ramp vl -> p (vl <= p) under a jerk limit with p = vhigh + w², and its
// derivative by w. With Δ = p - vl: D = (vl + p)/2 · T(Δ) and dD/dw = 2w · dD/dΔ, where
// dD/dΔ = T/2 + (vl + p)/2 · T'(Δ), T' = 1/a at full acceleration and 1/sqrt(j·Δ) below it.
struct DistanceSlope {
  double distance, slope;
};
DistanceSlope ramp_distance_by_w(double vl, double vhigh, double w, RampLimits l) {
  const double p = vhigh + w * w, dv = p - vl;
  if (dv <= 0) return {0.0, 0.0};
  if (dv >= l.accel * l.accel / l.jerk) {
    const double t = dv / l.accel + l.accel / l.jerk;
    return {0.5 * (vl + p) * t, w * t + (vl + p) * w / l.accel};
  }
  const double root = std::sqrt(dv * l.jerk);  // T = 2·sqrt(Δ/j) = 2·Δ/root, T' = 1/root
  const double t = 2.0 * dv / root;
  return {0.5 * (vl + p) * t, w * t + (vl + p) * (w / root)};
}

// The highest peak of a SOFT segment v0 -> peak -> v1 that fits `length`: the root of
// needed(p) = D(v0, p) + D(p, v1) - length on [vhigh, cap], where needed(vhigh) < length <
// needed(cap). In p the ramp from vhigh starts like a square root (infinite slope), so Newton
// overshoots below the bracket; in w = sqrt(p - vhigh) each ramp's distance is convex and
// increasing (jerk phases: (2·vhigh + w²)·w/sqrt(j) and (c + w²)·sqrt(d + w²)/sqrt(j); full
// acceleration: polynomials in w² with positive coefficients), so Newton from w(cap) descends
// monotonically onto the root. Once the distance is exact to 1e-12 of the length from above,
// a double step lands just below it: the result has needed <= length (the cruise is never
// negative). A step out of the bracket [lo, hi] bisects (rounding only).
// (Illinois regula falsi in p took ~15 steps; this solve is a hot spot on short SOFT blocks.)
double solve_peak(double v0, double v1, double vhigh, double cap, double length, RampLimits l) {
  auto f = [&](double w) {
    const DistanceSlope up = ramp_distance_by_w(v0, vhigh, w, l), down = ramp_distance_by_w(v1, vhigh, w, l);
    return DistanceSlope{up.distance + down.distance - length, up.slope + down.slope};
  };
  double lo = 0.0, hi = std::sqrt(cap - vhigh), x = hi;
  DistanceSlope fx = f(x);
  for (int i = 0; i < 100 && hi - lo > 1e-13 * hi; ++i) {
    const double step = fx.slope > 0 ? fx.distance / fx.slope : 0.5 * (hi - lo);
    double next = x - (fx.distance > 0 && fx.distance <= 1e-12 * length ? 2.0 * step : step);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    x = next;
    fx = f(x);
    if (fx.distance <= 0) {
      lo = x;
      if (fx.distance > -1e-12 * length) break;  // distance exact to rounding: done
    } else {
      hi = x;
    }
  }
  return vhigh + lo * lo;
}

}  // namespace

double ramp_time(double v0, double v1, RampLimits l) {
  double dv = std::abs(v1 - v0);
  if (!has_jerk_limit(l)) return dv / l.accel;
  if (dv >= l.accel * l.accel / l.jerk) return dv / l.accel + l.accel / l.jerk;
  return 2.0 * std::sqrt(dv / l.jerk);
}

double ramp_distance(double v0, double v1, RampLimits l) { return 0.5 * (v0 + v1) * ramp_time(v0, v1, l); }

double ramp_reach(double v0, double distance, RampLimits l) {
  if (distance <= 0) return v0;
  if (!has_jerk_limit(l)) return std::sqrt(v0 * v0 + 2.0 * l.accel * distance);
  const double a = l.accel, j = l.jerk;
  const double dv_star = a * a / j;  // smallest Δv that reaches full acceleration
  const double d_star = (2.0 * v0 + dv_star) * a / j;
  if (distance <= d_star) {
    // D = 2·v0·u + j·u³ with u = sqrt(Δv/j): one real root (Cardano, depressed cubic).
    // From rest (the braking ramp into the window's end) Cardano's root is u = cbrt(D/j)
    // exactly (sqrt(q²/4) = |q|/2 in IEEE arithmetic): taken directly, the same value.
    if (v0 == 0.0) {
      const double u = cube_root(distance / j);
      return j * u * u;
    }
    const double p = 2.0 * v0 / j, q = -distance / j;
    const double disc = std::sqrt(q * q / 4.0 + p * p * p / 27.0);
    // The two Cardano cube roots multiply to -p/3, so one cbrt gives both (cbrt is a hot spot).
    const double c = cube_root(-q / 2.0 + disc);
    const double u = c - p / (3.0 * c);
    return v0 + j * u * u;
  }
  // D = (2·v0 + Δv)/2 · (Δv/a + a/j): quadratic in Δv.
  const double qa = 1.0 / (2.0 * a);
  const double qb = v0 / a + a / (2.0 * j);
  const double qc = v0 * a / j - distance;
  const double dv = (-qb + std::sqrt(qb * qb - 4.0 * qa * qc)) / (2.0 * qa);
  return v0 + dv;
}

double reach_upper_bound(double v0, double distance, RampLimits l) {
  if (distance <= 0) return v0;
  const double brisk = std::sqrt(v0 * v0 + 2.0 * l.accel * distance);
  if (!has_jerk_limit(l)) return brisk;
  double bound = brisk;
  if (v0 > 0) {
    const double u = distance / (2.0 * v0);
    bound = std::min(bound, v0 + l.jerk * u * u);
  }
  return bound * (1.0 + 1e-12);
}

SegmentProfile plan_segment(double v0, double v1, double cap, double length, RampLimits l) {
  SegmentProfile p;
  p.v0 = v0;
  p.length = length;
  cap = std::max({cap, v0, v1});
  const double vlow = std::min(v0, v1), vhigh = std::max(v0, v1);
  if (length <= 0) {
    p.peak = vhigh;
    return p;
  }
  const double min_distance = ramp_distance(vlow, vhigh, l);
  if (min_distance > length * (1.0 + 1e-12)) {
    // A ramp that started in an earlier segment: v² changes linearly over this one.
    p.peak = vhigh;
    p.duration = 2.0 * length / (v0 + v1);
    p.phases[0] = {p.duration, (v1 * v1 - v0 * v0) / (2.0 * length), 0.0};
    p.phase_count = 1;
    return p;
  }
  auto needed = [&](double peak) { return ramp_distance(v0, peak, l) + ramp_distance(peak, v1, l); };
  double peak = cap;
  if (needed(cap) > length) {
    if (!has_jerk_limit(l)) {
      peak = std::sqrt((2.0 * l.accel * length + v0 * v0 + v1 * v1) / 2.0);
    } else if (min_distance >= length * (1.0 - 1e-12)) {
      peak = vhigh;  // the ramp v0 -> v1 fills the segment (to the solve's own tolerance)
    } else {
      peak = solve_peak(v0, v1, vhigh, cap, length, l);
    }
    peak = std::clamp(peak, vhigh, cap);
  }
  append_ramp(p, v0, peak, l);
  double cruise = length - needed(peak);
  if (cruise > 0 && peak > 0) p.phases[static_cast<size_t>(p.phase_count++)] = {cruise / peak, 0.0, 0.0};
  append_ramp(p, peak, v1, l);
  p.peak = peak;
  for (int i = 0; i < p.phase_count; ++i) p.duration += p.phases[static_cast<size_t>(i)].duration;
  return p;
}

ProfileState evaluate(const SegmentProfile& p, double t) {
  ProfileState st{0.0, p.v0, 0.0, 0.0};
  t = std::clamp(t, 0.0, p.duration);
  for (int i = 0; i < p.phase_count; ++i) {
    const ProfilePhase& ph = p.phases[static_cast<size_t>(i)];
    double dt = std::min(t, ph.duration);
    st.a = ph.accel_start;
    st.j = ph.jerk;
    st.s += st.v * dt + ph.accel_start * dt * dt / 2.0 + ph.jerk * dt * dt * dt / 6.0;
    st.v += ph.accel_start * dt + ph.jerk * dt * dt / 2.0;
    st.a = ph.accel_start + ph.jerk * dt;
    t -= dt;
    if (t <= 0 && i + 1 < p.phase_count && dt < ph.duration) break;
    if (t <= 0) break;
  }
  st.s = std::clamp(st.s, 0.0, p.length);
  st.v = std::max(st.v, 0.0);
  return st;
}

}  // namespace drycut::motion
