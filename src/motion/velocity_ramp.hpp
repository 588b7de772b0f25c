#pragma once
// Closed-form velocity changes along the path, used by the planner's passes and for timing.
//
// A ramp changes the path velocity from v0 to v1 starting and ending with zero acceleration.
// BRISK (jerk = infinity): constant acceleration a, an acceleration step at each end.
// SOFT: jerk-limited with jerk j and acceleration at most a. Because such a ramp's
// acceleration profile is symmetric in time, its distance is exactly (v0 + v1) / 2 · T.
//   |Δv| >= a²/j : T = |Δv|/a + a/j   (jerk phase, constant-acceleration phase, jerk phase)
//   |Δv| <  a²/j : T = 2·sqrt(|Δv|/j) (two jerk phases, peak acceleration sqrt(|Δv|·j))
#include <array>
#include <limits>

namespace drycut::motion {

inline constexpr double kNoJerkLimit = std::numeric_limits<double>::infinity();

struct RampLimits {
  double accel = 0;            // mm/s², > 0
  double jerk = kNoJerkLimit;  // mm/s³; infinity under BRISK
};

// Time of a ramp between v0 and v1 (either direction).
double ramp_time(double v0, double v1, RampLimits limits);
// Distance of that ramp.
double ramp_distance(double v0, double v1, RampLimits limits);
// Highest velocity reachable from v0 over `distance` (the inverse of ramp_distance).
double ramp_reach(double v0, double distance, RampLimits limits);
// An upper bound of ramp_reach that costs one square root (relative margin 1e-12 above the
// rounding of ramp_reach). Under SOFT the ramp's distance D = (v0 + v1)/2 · T with
// T >= (v1 - v0)/a gives v1 <= sqrt(v0² + 2·a·D), and T >= 2·sqrt(Δv/j) (both regimes, by
// AM-GM on Δv/a + a/j) gives Δv <= j·(D / (2·v0))²; the bound is the lower of the two.
// Under BRISK it is the reach itself.
double reach_upper_bound(double v0, double distance, RampLimits limits);

// One phase of constant jerk; the acceleration at its start is given (BRISK steps it).
struct ProfilePhase {
  double duration = 0;
  double accel_start = 0;
  double jerk = 0;
};

// The velocity profile over one segment of length L: ramp v0 -> peak, cruise, ramp -> v1;
// or, when the segment is too short for zero-acceleration ends (a ramp that runs across
// several segments), a single constant-acceleration phase between v0 and v1.
struct SegmentProfile {
  double v0 = 0;
  double length = 0;
  double peak = 0;        // highest velocity in the segment
  double duration = 0;
  std::array<ProfilePhase, 7> phases{};
  int phase_count = 0;
};

// v0, v1 <= cap; v0 -> v1 must be reachable in `length` under `limits`, with or without
// zero-acceleration ends (the planner's passes guarantee that).
SegmentProfile plan_segment(double v0, double v1, double cap, double length, RampLimits limits);

// State of a profile at local time t (clamped to [0, duration]).
struct ProfileState {
  double s = 0, v = 0, a = 0, j = 0;
};
ProfileState evaluate(const SegmentProfile& profile, double t);

}  // namespace drycut::motion
