#pragma once
// RND=r / RNDM=r at a corner where a circle meets a straight line or another circle (in the
// working plane): the rounding circle of radius r tangent to both (Fundamentals, "Contour
// corners: chamfer, rounding": the circle is inserted tangentially between the two contour
// elements, lines or circles).
//
// Algorithm. Each side is a line (a point and its unit direction) or a circle (centre O, radius
// R). At the corner C the incoming side ends with tangent t1, the outgoing one starts with t2;
// they turn towards w = the unit normal of t1 in the plane on the side t2 turns to. The rounding
// centre M lies at distance r on that inner side of both sides: on the line shifted by r along
// its inner normal, or on the circle of radius R + σr about O (σ = -1 when the inner side is
// towards O at C, +1 otherwise). Those two loci (line-line, line-circle, circle-circle) are
// intersected; of the solutions the one nearest C is M. The tangent points are the feet of M on
// the sides: P1 = M - r·n1 (line) or O + R·(M - O)/|M - O| (circle), P2 alike. The incoming side
// then ends at P1, the outgoing one starts at P2 (arc lengths s1, s2 along them; a point outside
// a side means the rounding does not fit: nullopt, the caller keeps the corner sharp and says
// so). The rounding runs from P1 with e1 = (P1 - M)/r, e2 = the incoming tangent at P1, through
// the angle from P1 to P2 about M (0 < sweep < π).
#include <optional>

#include "interp/geometry/curve.hpp"

namespace drycut::interp {

struct CurvedRounding {
  double end_of_first = 0;     // arc length at which the incoming side now ends
  double start_of_second = 0;  // arc length at which the outgoing side now starts
  geometry::CurvePtr curve;    // the rounding circle from P1 to P2
};

// `first` ends and `second` starts at the corner; each a LineCurve or a planar ArcCurve in the
// plane with unit normal `n`. nullopt: tangent sides (no corner), a reversal, or no fit.
std::optional<CurvedRounding> rounding_with_arcs(const geometry::CurvePtr& first, const geometry::CurvePtr& second,
                                                 double radius, const geometry::Vec3& n);

}  // namespace drycut::interp
