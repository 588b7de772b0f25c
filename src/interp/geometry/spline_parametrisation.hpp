#pragma once
// THE parametrisation choice for all splines built from programmed points (facts §1.3/§1.4 [I],
// §1.5 [I]): chord length. The parameter step from one point to the next is the straight
// distance between them, so along an A or C spline the derivative dP/du has magnitude close to
// 1 and end tangents (BTAN/ETAN) are unit vectors. For B splines the knot span a block owns is
// its PL value if programmed, else the same chord length between its control point and the
// previous one. Changing the rule here changes it for every spline type.
#include <algorithm>

#include "interp/geometry/curve.hpp"

namespace drycut::geometry {

// Points closer than this (mm) are the same point: a spline block to the same point has no span.
inline constexpr double kSplineSamePoint = 1e-9;

// Parameter step between consecutive spline points (A/C spline) or default B-spline knot span.
inline double parameter_step(const Vec3& from, const Vec3& to) { return (to - from).norm(); }

// B-spline knot span of a block: PL when programmed (> 0), else the chord. Never zero, so knots
// keep multiplicity 1 inside the curve even for repeated control points.
inline double bspline_knot_span(const Vec3& from, const Vec3& to, double programmed_pl) {
  if (programmed_pl > 0.0) return programmed_pl;
  return std::max(parameter_step(from, to), 1e-6);
}

}  // namespace drycut::geometry
