#pragma once
// The velocity profile over a long segment of a curved element, as the limit of cutting it into
// very short segments (the planner's rule before element_discretisation.hpp, which curved
// elements were timed by and still are within 0.1 %).
//
// The planner's passes follow a ramp across short segments from its ANCHOR, the node where it
// started, using ramp_reach (a ramp that starts AND ends with zero acceleration). A node at
// distance D from the anchor gets ramp_reach(v_anchor, D); each short segment between two such
// nodes is then run at constant acceleration. As the segments get shorter the velocity follows
// the ENVELOPE
//    v(x) = min(cap, R_rise(x), R_fall(x)),
//    R_rise(x) = ramp_reach(v_r, p_r + x),   R_fall(x) = ramp_reach(v_f, p_f + L - x)
// over the segment [0, L]: v_r, v_f are the velocities at the anchors of the ramp arriving from
// behind and of the ramp leaving ahead, p_r and p_f their distances from the segment's ends.
// (Under SOFT this is slower than one S-curve: from rest, 3·sqrt(Δv/j) instead of 2·sqrt(Δv/j).
// Under BRISK the envelope is the constant-acceleration ramp itself.)
//
// Time along an envelope from its anchor velocity v0 to v0 + u, with T = ∫ dD / v:
//   BRISK:               τ(u) = u / a
//   SOFT, u <= a²/j:     D(u) = (2·v0 + u)·sqrt(u/j),  dD/du = (3u + 2·v0) / (2·sqrt(j·u)),
//                        τ(u) = (3·w - sqrt(v0)·atan(w / sqrt(v0))) / sqrt(j),  w = sqrt(u)
//   SOFT, u > u* = a²/j: D(u) = (2·v0 + u)/2·(u/a + a/j),  dD/du = (v0 + u)/a + a/(2j),
//                        τ(u) = τ(u*) + (u - u*)/a + a/(2j)·ln((v0 + u)/(v0 + u*))
// GRID: near an anchor at low velocity the short segments do not converge quickly: from rest
// under SOFT, v ∝ D^(2/3) and 1/v is singular, so n segments of h at constant acceleration are
// faster than the envelope by about (h/j)^(1/3) per ramp (the first segment alone: 2·h/v1
// against 3·h/v1). To keep the times of the former rule (h = clamp(v·T_IPO, 0.01, 0.5) mm), the
// first kGridTerms segments of h from each anchor are timed as those segments were,
// 2·h / (v_m + v_m+1), instead of by τ; further out the two agree (the difference decays like
// m^(-8/3)). Under BRISK both are exact and equal.
//
// The segment time is the rise time, the cruise at the cap and the fall time; where the rise
// meets the fall below the cap, the meeting velocity solves D_r(v) + D_f(v) = L + p_r + p_f
// (bisection; both sides are increasing in v).
#include "motion/velocity_ramp.hpp"

namespace drycut::motion {

// One side of an envelope: the anchor velocity, its distance from the segment end it enters
// by, the ramp limits of the chain and its values at both ends (the passes know them).
struct EnvelopeSide {
  double anchor_velocity = 0;
  double offset = 0;
  RampLimits limits;
  double near = 0;  // the envelope at the end it enters by: ramp_reach(anchor, offset)
  double far = 0;   // and at the other end: ramp_reach(anchor, offset + length)
  double grid = 0;  // h of the equal segments this emulates (0: the continuous envelope)
};

struct EnvelopeSegment {
  double length = 0;
  double cap = 0;
  EnvelopeSide rise, fall;
  double peak = 0;                     // highest velocity (the cap or the meeting point)
  double x_rise = 0, x_fall = 0;       // the cruise at `peak` runs over [x_rise, x_fall]
  double u_rise0 = 0, u_rise1 = 0;     // rise: anchor-relative Δv at x = 0 and x = x_rise
  double u_fall0 = 0, u_fall1 = 0;     // fall: at x = L and at x = x_fall
  double t_rise = 0, t_cruise = 0, t_fall = 0;
  double t_rise_envelope = 0, t_fall_envelope = 0;  // before the grid correction (samples)
  double duration = 0;
};

// Time along an envelope from its anchor velocity v0 up to v0 + u.
double envelope_time(double v0, double u, RampLimits limits);

EnvelopeSegment plan_envelope_segment(double length, double cap, EnvelopeSide rise, EnvelopeSide fall);

// State at local time t (clamped to [0, duration]); for samples only (bisection per call).
ProfileState evaluate(const EnvelopeSegment& segment, double t);

}  // namespace drycut::motion
