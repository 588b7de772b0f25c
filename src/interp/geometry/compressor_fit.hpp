#pragma once
// The NC block compressor's fit (COMPON / COMPCURV / COMPCAD, docs/compressor.md): a run of
// programmed points P_0..P_n (the end points of simple G1 blocks) becomes cubic polynomial spans
// that stay inside the tolerance band around the programmed points and lines. Siemens does not
// publish its algorithm; this one is drycut's, chosen to be sound, local and O(n):
//
// 1. Corners. A point where the direction of the programmed polyline turns by more than the
//    corner angle (SD42470 CRIT_SPLINE_ANGLE) ends one piece and starts the next: the fit passes
//    that point exactly and may turn there (a tangent discontinuity the planner treats as a
//    corner). Pieces of one segment stay straight lines.
// 2. Parameter. Inside a piece the parameter is the cumulative chord length t_i (dP/dt ~ 1).
// 3. Knots. Knots are a subset of the programmed points; the fit interpolates them. Start: every
//    `max_segments_per_span` points (COMPON/COMPCURV: 10 blocks per polynomial, FB1); COMPCAD
//    starts with the piece's two ends only.
// 4. Curve through the knots, with end tangents from the parabola through the first (last) three
//    programmed points, or the tangent the previous window ended with:
//    - C1 (COMPON, 3rd degree, velocity-continuous): a cubic Hermite span per pair of knots, the
//      tangent at a knot from the parabola through the knot and its two programmed neighbours
//      (Bessel tangent) — local, no system to solve.
//    - C2 (COMPCURV, COMPCAD): the interpolating cubic spline through the knots (one tridiagonal
//      solve, cubic_spline_tangents.hpp): velocity- and acceleration-continuous. Siemens uses 5th
//      degree for COMPCURV (and MD20486 for COMPCAD); a C2 cubic has the same continuity of
//      velocity and acceleration, not of jerk.
// 5. Check. On every span: each programmed point inside it, S(t_i) against P_i, and three samples
//    of each programmed segment, S(t) against the point at the same share of the segment. These
//    vectors bound the distance to the programmed point and line from above, so the check is
//    conservative; a sample may only use `margin` (< 1) of the tolerance because the curve
//    between samples is not checked. The tolerance is per axis (MD33100, COMPRESSOR_MODE units
//    digit 0/2) or the Euclidean contour tolerance (SD42475, units digit 1/3).
// 6. Refine. Every span that fails gets its middle programmed point as a new knot; go to 4. A
//    span of a single programmed segment that still fails is given up: its segment stays a
//    straight line and the piece is split around it (so the loop always ends).
// Cost: each round is O(points of the piece); the rounds are about log2 of the initial knot
// spacing (COMPCAD: of the piece length in points). The caller bounds the piece length (BlockCompressor flushes its run).
#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "interp/geometry/curve.hpp"

namespace drycut::geometry {

enum class FitContinuity { C1, C2 };

struct CompressorFitOptions {
  FitContinuity continuity = FitContinuity::C2;
  size_t max_segments_per_span = 0;  // 0: unbounded (COMPCAD)
  bool contour_tolerance = false;    // true: |deviation| <= contour_tol; false: per axis
  double contour_tol_mm = 0.05;
  Vec3 axis_tol_mm = Vec3::Constant(0.1);
  double corner_angle_deg = 36.0;    // a sharper turn of the polyline is a corner
  double margin = 0.9;               // share of the tolerance the sampled check allows
};

// One output span over programmed points [first, last] (indices into the run's points).
// `curve` is null for a segment kept as the straight programmed line.
struct FittedSpan {
  size_t first = 0, last = 0;
  CurvePtr curve;
  double deviation_mm = 0.0;  // largest |S - programmed| over the checked points and samples
  Vec3 end_tangent = Vec3::UnitX();  // unit tangent at P_last
};

// points.size() >= 2, consecutive points distinct. start_tangent: a unit tangent the fit must
// leave P_0 with (continuing the previous window); nullopt: free.
std::vector<FittedSpan> fit_compressed_run(std::span<const Vec3> points, const CompressorFitOptions& options,
                                           std::optional<Vec3> start_tangent = std::nullopt);

}  // namespace drycut::geometry
