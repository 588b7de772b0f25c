#include "motion/envelope_segment.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace drycut::motion {
namespace {

// Distance from the side's segment end at which its envelope reaches v.
double distance_at(const EnvelopeSide& side, double v) {
  return ramp_distance(side.anchor_velocity, v, side.limits) - side.offset;
}

// dD/du along the envelope (see the header).
double distance_rate(double v0, double u, RampLimits l) {
  if (!std::isfinite(l.jerk)) return (v0 + u) / l.accel;
  const double u_star = l.accel * l.accel / l.jerk;
  if (u <= u_star) return u > 0 ? (3 * u + 2 * v0) / (2 * std::sqrt(l.jerk * u)) : std::numeric_limits<double>::infinity();
  return (v0 + u) / l.accel + l.accel / (2 * l.jerk);
}

// u with envelope_time(v0, u) - envelope_time(v0, u_lo) = t, by bisection (samples only).
double invert_time(double v0, double u_lo, double u_hi, double t, RampLimits l) {
  const double t0 = envelope_time(v0, u_lo, l);
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (u_lo + u_hi);
    if (envelope_time(v0, mid, l) - t0 < t) {
      u_lo = mid;
    } else {
      u_hi = mid;
    }
  }
  return 0.5 * (u_lo + u_hi);
}

// Path acceleration and jerk on an envelope at anchor-relative Δv = u (rising direction).
void envelope_dynamics(double v0, double u, RampLimits l, double& accel, double& jerk) {
  auto accel_at = [&](double w) {
    const double rate = distance_rate(v0, w, l);
    return std::isfinite(rate) ? (v0 + w) / rate : 0.0;
  };
  accel = accel_at(u);
  const double h = 1e-6 * (1.0 + u);
  const double lo = std::max(0.0, u - h);
  jerk = (accel_at(u + h) - accel_at(lo)) / (u + h - lo) * accel;
}

constexpr int kGridTerms = 3;

// Time of the first grid segments from the anchor that start in [d_lo, d_hi) (anchor
// distances) and end before `d_ramp_end`, as the former equal segments ran them, minus the
// envelope time over the same cells. A cell crossing into the next segment counts here.
double grid_correction(const EnvelopeSide& side, double d_lo, double d_hi, double d_ramp_end) {
  const double h = side.grid;
  if (h <= 0 || !std::isfinite(side.limits.jerk) || d_hi <= d_lo || d_lo >= kGridTerms * h) return 0.0;
  const double v0 = side.anchor_velocity;
  const double eps = 1e-9 * h;
  double correction = 0;
  double v_m = v0;
  for (int m = 0; m < kGridTerms && m * h < d_hi - eps && (m + 1) * h <= d_ramp_end + eps; ++m) {
    const double v_next = ramp_reach(v0, (m + 1) * h, side.limits);
    if (m * h >= d_lo - eps) {
      const double grid_time = 2 * h / (v_m + v_next);
      const double term = grid_time - (envelope_time(v0, v_next - v0, side.limits) -
                                       envelope_time(v0, v_m - v0, side.limits));
      correction += term;
      if (std::abs(term) < 1e-5 * grid_time) break;  // far from a standstill: nothing to correct
    }
    v_m = v_next;
  }
  return correction;
}

}  // namespace

double envelope_time(double v0, double u, RampLimits l) {
  if (u <= 0) return 0.0;
  if (!std::isfinite(l.jerk)) return u / l.accel;
  const double sj = std::sqrt(l.jerk);
  auto jerk_phase = [&](double w) {
    const double sv = std::sqrt(std::max(v0, 0.0));
    return (sv > 0 ? 3 * w - sv * std::atan(w / sv) : 3 * w) / sj;
  };
  const double u_star = l.accel * l.accel / l.jerk;
  if (u <= u_star) return jerk_phase(std::sqrt(u));
  return jerk_phase(std::sqrt(u_star)) + (u - u_star) / l.accel +
         l.accel / (2 * l.jerk) * std::log((v0 + u) / (v0 + u_star));
}

EnvelopeSegment plan_envelope_segment(double length, double cap, EnvelopeSide rise, EnvelopeSide fall) {
  EnvelopeSegment e;
  e.length = length;
  e.rise = rise;
  e.fall = fall;
  const double r0 = rise.near, r1 = rise.far;
  const double f0 = fall.far, f1 = fall.near;  // fall envelope at x = 0 and x = L
  const double v0 = std::min(r0, f0), v1 = std::min(r1, f1);
  cap = std::max({cap, v0, v1});
  e.cap = cap;
  // Highest velocity: the cap, or where the rising and the falling envelopes meet.
  double top;
  if (r1 <= f1) {
    top = r1;  // rises over the whole segment
  } else if (f0 <= r0) {
    top = f0;  // falls over the whole segment
  } else {
    // g(v) = D_rise(v) + D_fall(v) - L rises with v: Newton inside a shrinking bracket.
    double lo = std::max(r0, f1), hi = std::min(r1, f0);
    auto g = [&](double v) { return distance_at(rise, v) + distance_at(fall, v) - length; };
    auto slope = [&](double v) {
      return distance_rate(rise.anchor_velocity, v - rise.anchor_velocity, rise.limits) +
             distance_rate(fall.anchor_velocity, v - fall.anchor_velocity, fall.limits);
    };
    top = hi;
    for (int i = 0; i < 60 && hi - lo > 1e-12 * hi; ++i) {
      const double value = g(top);
      if (std::abs(value) <= 1e-12 * (length + 1.0)) break;
      (value < 0 ? lo : hi) = top;
      const double rate = slope(top);
      const double next = std::isfinite(rate) && rate > 0 ? top - value / rate : 0.5 * (lo + hi);
      top = (next > lo && next < hi) ? next : 0.5 * (lo + hi);
    }
  }
  top = std::min(top, cap);
  e.peak = std::max({top, v0, v1});
  e.x_rise = top > r0 ? std::clamp(distance_at(rise, top), 0.0, length) : 0.0;
  e.x_fall = top > f1 ? std::clamp(length - distance_at(fall, top), e.x_rise, length) : length;
  if (e.x_rise > 0) {
    e.u_rise0 = r0 - rise.anchor_velocity;
    e.u_rise1 = top - rise.anchor_velocity;
    e.t_rise = envelope_time(rise.anchor_velocity, e.u_rise1, rise.limits) -
               envelope_time(rise.anchor_velocity, e.u_rise0, rise.limits);
  }
  if (e.x_fall < length) {
    e.u_fall0 = f1 - fall.anchor_velocity;
    e.u_fall1 = top - fall.anchor_velocity;
    e.t_fall = envelope_time(fall.anchor_velocity, e.u_fall1, fall.limits) -
               envelope_time(fall.anchor_velocity, e.u_fall0, fall.limits);
  }
  e.t_cruise = e.x_fall > e.x_rise ? (e.x_fall - e.x_rise) / top : 0.0;
  e.t_rise_envelope = e.t_rise;
  e.t_fall_envelope = e.t_fall;
  // A ramp that reaches the other end of the segment goes on in the next one.
  const double inf = std::numeric_limits<double>::infinity();
  if (e.x_rise > 0) {
    const double d_end = rise.offset + e.x_rise;
    e.t_rise += grid_correction(rise, rise.offset, d_end, e.x_rise < length * (1 - 1e-9) ? d_end : inf);
  }
  if (e.x_fall < length) {
    const double d_end = fall.offset + length - e.x_fall;
    e.t_fall += grid_correction(fall, fall.offset, d_end, e.x_fall > length * 1e-9 ? d_end : inf);
  }
  e.duration = e.t_rise + e.t_cruise + e.t_fall;
  return e;
}

ProfileState evaluate(const EnvelopeSegment& e, double t) {
  t = std::clamp(t, 0.0, e.duration);
  ProfileState st;
  if (t < e.t_rise) {
    const EnvelopeSide& side = e.rise;
    // Samples follow the envelope, stretched onto the (grid-corrected) rise time.
    const double u = invert_time(side.anchor_velocity, e.u_rise0, e.u_rise1, t * e.t_rise_envelope / e.t_rise, side.limits);
    st.v = side.anchor_velocity + u;
    st.s = std::clamp(distance_at(side, st.v), 0.0, e.length);
    envelope_dynamics(side.anchor_velocity, u, side.limits, st.a, st.j);
  } else if (t <= e.t_rise + e.t_cruise || e.t_fall <= 0) {
    st.v = e.peak;
    st.s = std::min(e.x_rise + e.peak * (t - e.t_rise), e.length);
  } else {
    const EnvelopeSide& side = e.fall;
    const double u = invert_time(side.anchor_velocity, e.u_fall0, e.u_fall1,
                                 (e.duration - t) * e.t_fall_envelope / e.t_fall, side.limits);
    st.v = side.anchor_velocity + u;
    st.s = std::clamp(e.length - distance_at(side, st.v), 0.0, e.length);
    envelope_dynamics(side.anchor_velocity, u, side.limits, st.a, st.j);
    st.a = -st.a;
  }
  return st;
}

}  // namespace drycut::motion
