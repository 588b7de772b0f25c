#pragma once
// Where the planner puts the nodes of a curved element (arc, helix, spline span, offset curve).
// The cost of an element follows the variation of its limits, not its length.
//
// RULE
// ====
// A segment between two nodes is planned with the LOWER velocity bound and the lower ramp
// limits (tangential acceleration and jerk) of its two end nodes. That is the exact worst case
// over the segment when every per-axis quantity the limits read (|t_i|, |κ_i|, |P'''_i|) is
// monotone on it. The discretiser therefore
//
// Only curves with a closed form below (circles and helices) are cut this way; their segments
// are then timed along the ramp envelope (envelope_segment.hpp), which is what the short equal
// segments used before converge to. Other curves (spline spans, offset curves) keep short equal
// segments of h = clamp(v_ref·T_IPO, 0.01 mm, 0.5 mm) (v_ref = F, or the rapid velocity): their
// planned times depend on h itself (up to 0.3 % between h and h/10 on the reference
// experiment), so a coarser rule would change them.
//
// 1. Cuts at the CRITICAL points, where that is known in closed form. On a circle or helix
//    (geometry::ArcCurve: centre c, radius r, plane axes e1, e2, normal n, pitch p per radian)
//      radial_i(φ) = e1_i cos φ + e2_i sin φ = R_i cos(φ - α_i),  R_i = |(e1_i, e2_i)|,
//      along_i(φ)  = radial_i'(φ)             = -R_i sin(φ - α_i),
//      t_i ∝ r·along_i + p·n_i,   κ_i ∝ radial_i,   P'''_i ∝ along_i,
//    so every quantity is monotone between the angles φ = α_i + k·π/2 (zeros and extremes of
//    radial_i and along_i: the quadrant points in the working plane) and, on a helix, the
//    angles where t_i = 0 (sin(φ - α_i) = p·n_i / (r·R_i)). An axis along n (Z under G17) is
//    constant.
//
// 2. Refines each piece [a, b] while a limit really varies on it: with the velocity bound v and
//    the ramp limits (acceleration A, jerk J; jerk only under SOFT) evaluated at a, at the
//    midpoint m and at b, the piece is halved while
//       max(v) > (1 + bound_tolerance) · min(v)   over {a, m, b}, or the same for A or J with
//       ramp_tolerance,
//    down to min_piece_mm. The bound already includes the constant limits (programmed F, the
//    short-block limit): where F binds over the whole piece, v is the same at all three points
//    and nothing is split, however long the arc. On an arc at the feed the cost is the number of
//    critical points in its sweep (at most 4 per turn and axis, plus 2 per helix turn and axis).
//
// 3. equal_segments replaces all of this by equal segments of fixed_segment_mm (when > 0) or of
//    h for every curve (test references: the former rule, or very fine segments).
//
// At most max_segments segments per element. Lines never come here (one segment).
#include <functional>
#include <vector>

#include "interp/path_element.hpp"
#include "motion/element_dynamics.hpp"
#include "motion/path_constraints.hpp"

namespace drycut::motion {

// One node candidate: its place on the element and the limits that hold there.
struct Station {
  double s = 0;  // arc length from the element's start
  CurvePoint point;
  VelocityBound bound;
  RampLimits ramp;
  // The worst case over the piece that ends here (the segment's cap and ramp limits).
  VelocityBound piece_bound;
  RampLimits piece_ramp;
};

struct DiscretisationRule {
  double bound_tolerance = 0.02;
  double ramp_tolerance = 0.05;
  double min_piece_mm = 1e-3;
  bool equal_segments = false;  // reference: equal segments of fixed_segment_mm, or of h
  double fixed_segment_mm = 0;
  int max_segments = 20000;
};

// The limits at a point (the returned station's s is set by the caller).
using PointLimits = std::function<Station(const CurvePoint& point)>;

// Fills `out` with the stations of a curved element of length `length`, the start (s = 0)
// first and the end (s = length) last. `limits_at` gives the limits at a point;
// `fine_step_mm` is h for curves without a closed form. Returns true when the stations are
// the adaptive pieces (time their segments along the envelope), false for equal segments.
bool discretise_element(const geometry::Curve& curve, double length, double fine_step_mm,
                        const DiscretisationRule& rule, const PointLimits& limits_at,
                        std::vector<Station>& out);

}  // namespace drycut::motion
