#pragma once
// Where to put the knots of a spline (or the vertices of a polygon) on a curve. The reference
// experiment used a polar angle step and equal arc length per quadrant; equal chord and
// curvature-adaptive spacing are ours.
#include <vector>

#include "workload/curve_source.hpp"

namespace drycut::workload {

struct Knot {
  double t = 0.0;  // curve parameter (θ in radians for polar curves)
  Vec3 point = Vec3::Zero();
};

// One knot every `step` of the parameter from t_begin (exclusive of t_end): 360 knots for 1°.
std::vector<Knot> parameter_step_knots(const CurveSource& curve, double step);

// Per quadrant of a closed polar curve, n knots at equal arc length along the true curve with
// both quadrant ends included; 4n-4 distinct knots (EXPERIMENT.md §2).
std::vector<Knot> equal_arc_per_quadrant_knots(const CurveSource& curve, int per_quadrant);

// `count` knots at equal arc length over the whole (closed) curve, the first at t_begin.
std::vector<Knot> equal_arc_knots(const CurveSource& curve, int count);

// Knots placed so that the chord between neighbours deviates from the curve by at most
// `tolerance` mm (sagitta from the local curvature), walking along the curve.
std::vector<Knot> chord_error_knots(const CurveSource& curve, double tolerance);

}  // namespace drycut::workload
