#pragma once
// The ways a SINUMERIK program can define a circle (facts §4.7), each turned into an ArcCurve
// (or, for a degenerate CT, a LineCurve). Failures come back as a SINUMERIK alarm number and a
// detail text instead of an exception, so the interpreter can attach the block location.
//
// Conventions: `clockwise` = G2, judged looking against the plane normal (G17: from +Z down;
// G18: from +Y, plane axes (Z, X); G19: from +X, plane axes (Y, Z)). Motion along the plane
// normal between start and end makes a helix. Angles in radians.
#include <string>

#include "interp/geometry/curve.hpp"
#include "interp/geometry/plane.hpp"

namespace drycut::geometry {

// MD21000 CIRCLE_ERROR_CONST (mm) and MD21010 CIRCLE_ERROR_FACTOR.
struct ArcTolerance {
  double error_const_mm = 0.01;
  double error_factor = 0.001;
};

struct ArcResult {
  CurvePtr curve;
  int alarm = 0;       // SINUMERIK alarm number, 0 = ok
  std::string detail;  // why, with the numbers, when alarm != 0
  bool ok() const { return alarm == 0; }
};

// G2/G3 with end point and centre (I/J/K). start == end in the plane is a full circle (2 pi).
// `turns` = TURN (extra full revolutions; negative -> 14048). The radius check: |r_start - r_end|
// must be <= max(error_const, r_start * error_factor), else 14040. Within tolerance the centre is
// moved to the nearest point of the perpendicular bisector of the chord (so start and end lie
// exactly on the circle); the radius becomes the distance from that centre to the start point.
ArcResult arc_from_center(Vec3 start, Vec3 end, Vec3 centre, bool clockwise, Plane plane, int turns,
                          const ArcTolerance& tolerance);

// G2/G3 with CR=: CR > 0 sweeps <= 180 deg, CR < 0 more than 180 deg. start == end (full circle)
// and CR = 0 -> 14040. A chord longer than 2|CR| by at most the tolerance is taken as a half circle;
// longer -> 14040. `turns` (TURN=) full revolutions are added before the end point (helix).
ArcResult arc_from_radius(Vec3 start, Vec3 end, double cr_signed, bool clockwise, Plane plane,
                          const ArcTolerance& tolerance = {}, int turns = 0);

// G2/G3 with AR= and centre: the in-plane end follows from the angle; `end` only gives the
// travel along the plane normal (a helix when it differs from the start's). AR outside
// (0, 2 pi] -> 12160. `turns` full revolutions are added (TURN=).
ArcResult arc_from_angle_and_center(Vec3 start, Vec3 end, Vec3 centre, double ar_rad, bool clockwise, Plane plane,
                                    int turns = 0);

// G2/G3 with AR= and end point. AR outside (0, 2 pi) -> 12160; start == end -> 14040.
// `turns` full revolutions are added (TURN=).
ArcResult arc_from_angle_and_end(Vec3 start, Vec3 end, double ar_rad, bool clockwise, Plane plane, int turns = 0);

// CIP: the arc from start through intermediate to end, in the 3-D plane of the three points.
// Coincident or collinear points -> 14040.
ArcResult arc_through_point(Vec3 start, Vec3 intermediate, Vec3 end);

// CT: the arc in `plane` that leaves start along start_tangent (projected into the plane) and
// ends at end. If end lies straight ahead on the tangent the result is a LineCurve; straight
// behind, or no tangent component in the plane, or start == end -> 14040.
ArcResult arc_tangent(Vec3 start, Vec3 start_tangent, Vec3 end, Plane plane,
                      const ArcTolerance& tolerance = {});

}  // namespace drycut::geometry
