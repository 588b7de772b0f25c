#pragma once
// Where the planner puts the nodes of a curved element (arc, helix, spline span, offset curve).
// On a circle or helix the cost follows the variation of its limits, not its length.
//
// RULE
// ====
// Every point constraint (path_constraints.hpp) and the ramp limits (tangential_limits) are a
// minimum over the axes of a function that falls as |t_i|, |κ_i| or |P'''_i| grows. So the
// worst case of all of them over a stretch of a curve is their value at one synthetic WORST
// POINT whose components are the per-axis maxima of |t_i|, |κ_i|, |P'''_i| over the stretch.
//
// Circles and helices (geometry::ArcCurve: radius r, plane axes e1, e2, normal n, pitch p per
// radian, φ the angle) have these maxima in closed form:
//    radial_i(φ) = e1_i cos φ + e2_i sin φ = R_i cos(φ - α_i),  R_i = |(e1_i, e2_i)|,
//    along_i(φ)  = radial_i'(φ)             = -R_i sin(φ - α_i),
//    t_i = (r·along_i + p·n_i)/S,  κ_i = -r/S²·radial_i,  P'''_i ∝ r/S³·along_i,  S = sqrt(r²+p²)
// each is a sinusoid (plus a constant for a helix tangent): its largest magnitude over a swept
// angle is at an end of the sweep or at an interior extreme, φ = α_i + k·π/2 (the quadrant
// points in the working plane). An axis along n (Z under G17) is constant.
//
// 1. The whole element is ONE piece; its segment gets the limits of its worst point.
// 2. The piece is accepted when that worst case is within bound_tolerance (2 %) of the better
//    end's velocity bound (the bound includes F and the short-block limit, so an arc whose
//    varying limits all stay above F is never cut, however long) and, on a circle whose bound
//    the geometry sets, of the bound at its BEST POINT too (per axis the smallest |t_i|, |κ_i|,
//    |P'''_i| over the piece: the best it offers anywhere; a full circle from a quadrant point
//    has both ends at its worst and its best limits at 45 degrees), and, where a ramp can run
//    (within the distance of a ramp from rest to the bound from either end of the element),
//    within ramp_tolerance (5 %) for the ramp jerk and for the ramp acceleration; under SOFT a
//    ramp up to v is at the acceleration limit only for the part of Δv above a²/j, so there
//    the acceleration may vary by ramp_tolerance · v / (v - a²/j) (not checked when v <= a²/j).
// 3. Otherwise it is cut at the CRITICAL angles inside it (the extremes above and, on a helix,
//    the zeros of t_i, sin(φ - α_i) = p·n_i/(r·R_i)), where every component becomes monotone,
//    or, when there are none, in halves; the pieces go back to step 2 (min_piece_mm, at most
//    max_segments per element).
// Segments of these pieces are timed along the ramp envelope (envelope_segment.hpp), which is
// what the short equal segments used before converge to.
//
// Other curves (spline spans, offset curves) have no closed form. One not longer than
// h = clamp(v_ref·T_IPO, 0.01 mm, 0.5 mm) (v_ref = F, or the rapid velocity) is one segment with
// the lower limits of its two ends (the former rule, so CAM-short spans keep their times). A
// longer one is SAMPLED, by the variation of its own limits:
// 4. The piece [a, b] is evaluated at its midpoint m too; its worst point takes per axis the
//    largest |t_i|, |κ_i|, |P'''_i| (and the largest curvature) of a, m, b. On a spline span m
//    is the midpoint of the span's own parameter, its arc length read forward from the span's
//    arc-length table (one Gauss integral); elsewhere the midpoint in arc length. Either halves
//    the piece; the parameter's saves the inversion s -> u (Newton steps of Gauss integrals,
//    a sixth of the planner's work on BSPLINE programs), and planned times moved by 1e-9.
// 5. It is accepted when the tangent turns by at most max_sampled_turn (0.05 rad) from a to m
//    and from m to b (each component then moves like a cosine over a small angle, and an
//    extreme between samples exceeds the nearest one by at most 1 - cos(0.025), 0.03 %), and
//    the worst case passes step 2 with the tighter sampled tolerances (0.2 %, ramps 0.2 %);
//    otherwise it is halved at m (min_piece_mm, max_segments as above).
// 6. A piece whose velocity bound varies beyond that tolerance is still accepted when its three
//    samples are monotone (a <= m <= b or a >= m >= b, so the sampled worst case w is the bound
//    of its lower end), that end is no local minimum of the samples (the sample beyond it is
//    lower still; next to a sampled minimum the true one may hide between samples), and the
//    planner could not use the variation: a ramp from w over the whole piece rises by at most
//    sampled_reach_tolerance (1e-4) of w. Finer pieces would start their profile at that end at
//    most at w and could not rise faster than that ramp, so capping the piece at w costs about
//    that fraction of its time at most. Spline spans whose jerk bound dips steeply (BSPLINE
//    spans over short control legs: v = cbrt(j_i / |d3P_i/ds3|) falls by 10 % within 0.02 mm)
//    were otherwise halved down to min_piece_mm on both flanks of each dip (~66 samples and
//    ~33 pieces per such span); the pieces at the dip's bottom are still halved as before.
// These pieces are timed along the envelope like arcs. The former equal segments' times depended
// on h (up to 0.7 % from a 0.005 mm reference under BRISK on long, tightly curved spans): the
// sampled pieces are within 0.1 % of that reference under BRISK and of the h segments under
// SOFT (near standstills, where the envelope's grid keeps h).

// equal_segments replaces all of this by equal segments of fixed_segment_mm (when > 0) or of h
// for every curve (test references: the former rule, or very fine segments).
// Lines never come here (one segment).
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
  double max_sampled_turn = 0.05;  // rad, tangent turn between samples of a sampled piece
  double sampled_bound_tolerance = 0.002;  // tolerances of sampled pieces (no closed form)
  double sampled_ramp_tolerance = 0.002;
  double sampled_reach_tolerance = 1e-4;  // step 6: relative rise of a ramp over a monotone piece
  bool equal_segments = false;  // reference: equal segments of fixed_segment_mm, or of h
  double fixed_segment_mm = 0;
  int max_segments = 20000;
};

// The limits that hold at one point (a station's bound and ramp).
struct LocalLimits {
  VelocityBound bound;
  RampLimits ramp;
};

// The limits at a point. Only these 32 bytes come back: the discretiser builds each station
// itself (its curve point in place), and a worst point's limits need no station at all.
using PointLimits = std::function<LocalLimits(const CurvePoint& point)>;

// Fills `out` with the stations of a curved element of length `length`, the start (s = 0)
// first and the end (s = length) last. `limits_at` gives the limits at a point;
// `fine_step_mm` is h for curves without a closed form. Returns true when the stations are
// the adaptive pieces (time their segments along the envelope), false for equal segments.
bool discretise_element(const geometry::Curve& curve, double length, double fine_step_mm,
                        const DiscretisationRule& rule, const PointLimits& limits_at,
                        std::vector<Station>& out);

}  // namespace drycut::motion
