#pragma once
// Tool-centre geometry at the joint of two programmed elements (SINUMERIK group 18):
//   G450: transition circle of the tool radius around the programmed corner point;
//   G451: the offset lines' intersection (a point reached by two straight moves), except at
//         corners sharper than the corner limit, where the control switches to the circle.
// Inside corners never get a corner element: the offset paths are intersected (trimmed) instead.
#include <numbers>
#include <vector>

#include "interp/cutter_compensation_piece.hpp"

namespace drycut::interp {

// Direction change above which G451 falls back to the G450 circle at an outside corner
// (MD20210 CUTCOM_CORNER_LIMIT, 100 degrees; an intersection point would run away otherwise).
inline constexpr double kCornerLimitRad = 100.0 * std::numbers::pi / 180.0;

// Unit in-plane direction of `v` (zero when v is parallel to the plane normal).
geometry::Vec3 plane_direction(const geometry::Vec3& v, const CompensationPlane& plane);

// The tool is on the outer side of the turn from t_in to t_out (offset d: + left, - right).
// A reversal (180 degrees) counts as outside.
bool is_outside_corner(const geometry::Vec3& t_in, const geometry::Vec3& t_out, double offset_mm,
                       const CompensationPlane& plane);

// Curves from corner + d n x t_in to corner + d n x t_out around an outside corner.
std::vector<geometry::CurvePtr> outside_corner_curves(const geometry::Vec3& corner, const geometry::Vec3& t_in,
                                                      const geometry::Vec3& t_out, double offset_mm,
                                                      bool intersection_corners, const CompensationPlane& plane);

}  // namespace drycut::interp
