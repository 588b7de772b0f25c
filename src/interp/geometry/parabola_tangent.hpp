#pragma once
// Derivative at an end of the parabola through three consecutive spline points, with the
// chord-length parameter (steps h0 = |p1 - p0|, h1 = |p2 - p1|). Used for BAUTO/EAUTO of the
// Akima spline and where a windowed cubic spline is cut off.
#include "interp/geometry/curve.hpp"

namespace drycut::geometry {

// dP/du at p0 of the parabola through p0 (u=0), p1 (u=h0), p2 (u=h0+h1).
inline Vec3 parabola_start_tangent(const Vec3& p0, const Vec3& p1, const Vec3& p2, double h0, double h1) {
  const Vec3 d0 = (p1 - p0) / h0, d1 = (p2 - p1) / h1;
  return d0 - h0 * (d1 - d0) / (h0 + h1);
}

// dP/du at p2 of the same parabola.
inline Vec3 parabola_end_tangent(const Vec3& p0, const Vec3& p1, const Vec3& p2, double h0, double h1) {
  const Vec3 d0 = (p1 - p0) / h0, d1 = (p2 - p1) / h1;
  return d1 + h1 * (d1 - d0) / (h0 + h1);
}

}  // namespace drycut::geometry
