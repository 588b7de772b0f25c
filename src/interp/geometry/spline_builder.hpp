#pragma once
// Splines built while streaming a run of spline blocks (ASPLINE / CSPLINE / BSPLINE).
//
// Protocol: add_point() first with the start point (the position before the run, index 0), then
// once per spline block (index 1, 2, ...); finish() after the last block; pop_span() hands out
// every span that is final, in order, possibly long before finish() (A and C splines only look a
// few points ahead, so a run of a million blocks is never held in memory; the exception is the
// global C spline, window 0). A span's block_index is the add_point index of the block it belongs
// to. A block owns at most one span, so block indices of consecutive spans strictly increase (the
// interpreter's SplineRun moves a block's element into its span). A block may own no span: a
// block to the same point as the previous one, and for B splines the last degree-1 blocks (see
// make_nurbs_builder).
// Bad values (non-finite coordinates, PW outside [0, 3]) throw AlarmError 12160 without a
// source location; the interpreter re-raises it with the block's location.
#include <memory>

#include "interp/geometry/curve.hpp"

namespace drycut::geometry {

enum class EndCondition { Natural, Tangent, Auto };  // BNAT/ENAT, BTAN/ETAN, BAUTO/EAUTO

struct SplineEnd {
  EndCondition condition = EndCondition::Natural;
  Vec3 tangent = Vec3::Zero();  // unit direction, for Tangent
};

struct SplineSpan {
  CurvePtr curve;
  size_t block_index = 0;
};

class SplineBuilder {
 public:
  virtual ~SplineBuilder();
  // weight = PW (1 by default), knot_span = PL (<= 0: not programmed); A/C splines ignore both.
  virtual void add_point(const Vec3& p, double weight, double knot_span) = 0;
  // No more points. ETAN tangent = start direction of the next motion.
  virtual void finish(const SplineEnd& end) = 0;
  // Next final span; false when none is ready yet (or all were handed out).
  virtual bool pop_span(SplineSpan& out) = 0;
};

// ASPLINE: Akima, chord-length parameter, one cubic per block, C1. Tangent at point i from the
// classical Akima rule per axis over the chord slopes m_{i-2}..m_{i+1}. End handling: the tangent
// at the first (last) point comes from the end condition: Tangent = the given unit direction;
// Natural = zero second derivative of the first (last) cubic; Auto = derivative of the parabola
// through the first (last) three points. The Akima rule at the second (second-to-last) point
// needs one slope beyond the run, extrapolated linearly as m_{-1} = 2 m_0 - m_1 (Akima 1970).
// Runs of two points give the straight line (Natural/Auto) or a Hermite cubic (Tangent).
std::unique_ptr<SplineBuilder> make_akima_builder(const SplineEnd& begin);

// CSPLINE: cubic, chord-length parameter, one cubic per block. window_blocks = MD20160:
//  0  -> one global C2 spline through the whole run, solved at finish (holds the run).
//  W>0 -> the tangent at interior point j is that of the cubic spline through the points
//         j-h..j+h, h = max(2, W/2) (clipped to the run), using the run's end conditions where
//         the window reaches a run end and the 3-point parabola tangent where it is cut off.
//         The first and last tangents are then derived from their neighbours so that the end
//         condition holds exactly for the end spans. Consecutive spans share tangents: C1
//         exactly, C2 to within the window effect (decays like 0.27 per point).
//         Span i is final once point i+h+1 has arrived.
// End conditions: Natural P''=0, Tangent P' = unit direction, Auto = not-a-knot.
std::unique_ptr<SplineBuilder> make_cubic_builder(const SplineEnd& begin, int window_blocks);

// BSPLINE: NURBS with the programmed points as control points P0..Pn (P0 = start point), weights
// PW, degree SD (2 or 3; other values throw 12160), clamped knot vector. Knot layout: the first
// and last p+1 knots coincide; the j-th non-empty knot span (j = 1..n-p+1) has length
// bspline_knot_span(P_{j-1}, P_j, PL_j) of block j, and block j owns that span. The last p-1
// blocks own no span (their PL is unused; the curve still ends at P_n within block n-p+1's
// span). With fewer than p+1 control points the degree is reduced to n (n = 1: a straight line).
// Span j is final once point j+2p-2 has arrived.
std::unique_ptr<SplineBuilder> make_nurbs_builder(int degree);

}  // namespace drycut::geometry
