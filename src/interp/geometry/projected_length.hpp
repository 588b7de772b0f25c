#pragma once
// The length of a curve counted on some of its axes only: what the path feed F refers to when the
// feed group (FGROUP) names only some geometry axes. FGROUP(X,Y) on a helix: F is the speed along
// the circle in the plane, Z follows (PGA Fundamentals "Feedrate (G93, G94, G95, F, FGROUP)").
//
// L_axes = integral over the arc length s of |M·t(s)|, where t is the unit tangent and M keeps
// the components of the axes in the mask. A line: |M·(end - start)|, exact. Any other curve:
// composite 5-node Gauss-Legendre on 16 equal pieces of s; exact for a helix (|M·t| is constant
// when M keeps its plane, with or without the normal axis); where |M·t| has kinks (a circle
// counted on one of its plane axes) the error stays below 1e-4 of the length.
#include "interp/geometry/curve.hpp"

namespace drycut::geometry {

// axes: bit 0 X, bit 1 Y, bit 2 Z (7 = all: the curve's own length).
double projected_length(const Curve& curve, unsigned axes);

}  // namespace drycut::geometry
