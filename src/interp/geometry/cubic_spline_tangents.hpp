#pragma once
// Tangents dP/du at the points of an interpolating C2 cubic spline (one cubic per interval,
// parameter steps given), from the classical tridiagonal system
//   h_i m_{i-1} + 2 (h_{i-1} + h_i) m_i + h_{i-1} m_{i+1} = 3 (h_i d_{i-1} + h_{i-1} d_i),
// d_i = (p_{i+1} - p_i) / h_i, closed by one end condition per side.
// The windowed CSPLINE solves one such system per point: its scratch (CubicSplineScratch) is
// kept by the caller, so a solve allocates nothing once the vectors have grown.
#include <span>
#include <vector>

#include "interp/geometry/curve.hpp"

namespace drycut::geometry {

struct TangentCondition {
  enum class Kind { Natural, Clamped, NotAKnot };
  Kind kind = Kind::Natural;
  Vec3 tangent = Vec3::Zero();  // dP/du for Clamped
};

// points.size() == steps.size() + 1 >= 2, every step > 0. Not-a-knot needs three points; with
// two it falls back to Natural, and with exactly three and not-a-knot at both ends the result is
// the parabola through them.
std::vector<Vec3> cubic_spline_tangents(std::span<const Vec3> points, std::span<const double> steps,
                                        const TangentCondition& begin, const TangentCondition& end);

// The same solve in reusable scratch; the tangents are `tangents` (valid until the next call).
struct CubicSplineScratch {
  std::vector<Vec3> slopes, rhs, tangents;
  std::vector<double> lower, diag, upper;
};
std::span<const Vec3> cubic_spline_tangents(std::span<const Vec3> points, std::span<const double> steps,
                                            const TangentCondition& begin, const TangentCondition& end,
                                            CubicSplineScratch& scratch);

// The tangent at point j alone, the same system's solution: the rows above j are eliminated
// downwards and the rows below j upwards (two half Thomas sweeps meeting at row j), so a
// windowed CSPLINE gets its one tangent per window with no back substitution and no scratch.
// Equal to cubic_spline_tangents(...)[j] up to rounding.
Vec3 cubic_spline_tangent_at(std::span<const Vec3> points, std::span<const double> steps,
                             const TangentCondition& begin, const TangentCondition& end, size_t j);

}  // namespace drycut::geometry
