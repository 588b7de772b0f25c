#pragma once
// Tool-centre geometry at the joint of two programmed elements (SINUMERIK group 18):
//   G450: transition circle of the tool radius around the programmed corner point, except at
//         corners flatter than MD20230 CUTCOM_CURVE_INSERT_LIMIT, where the control switches to
//         the intersection (a circle there would only cost velocity in G64, W1 / MD20230);
//   G451: the offset lines' intersection (a point reached by two straight moves), except at
//         corners sharper than MD20210 CUTCOM_CORNER_LIMIT, where the control switches to the
//         circle (the intersection point would run far away).
// Both limits are direction changes in degrees (docs/controller-state.md, "Outside corners").
// Inside corners never get a corner element: the offset paths are intersected (trimmed) instead.
#include <vector>

#include "interp/cutter_compensation_piece.hpp"
#include "machine/machine_profile.hpp"

namespace drycut::interp {

// Which element an outside corner gets: the programmed G450/G451 and the machine's two limits.
struct OutsideCornerRule {
  bool intersection = false;          // G451 programmed
  double corner_limit_rad = 0;        // MD20210: G451 -> circle above this direction change
  double curve_insert_limit_rad = 0;  // MD20230: G450 -> intersection below it

  static OutsideCornerRule of(bool intersection_programmed, const machine::MachineProfile& profile);
  // True: the offsets meet at their intersection; false: the transition circle.
  bool intersects(double direction_change_rad) const;
};

// Unit in-plane direction of `v` (zero when v is parallel to the plane normal).
geometry::Vec3 plane_direction(const geometry::Vec3& v, const CompensationPlane& plane);

// The tool is on the outer side of the turn from t_in to t_out (offset d: + left, - right).
// A reversal (180 degrees) counts as outside.
bool is_outside_corner(const geometry::Vec3& t_in, const geometry::Vec3& t_out, double offset_mm,
                       const CompensationPlane& plane);

// Curves from corner + d n x t_in to corner + d n x t_out around an outside corner: two straight
// pieces meeting at the offsets' intersection, or one transition circle.
std::vector<geometry::CurvePtr> outside_corner_curves(const geometry::Vec3& corner, const geometry::Vec3& t_in,
                                                      const geometry::Vec3& t_out, double offset_mm,
                                                      const OutsideCornerRule& rule,
                                                      const CompensationPlane& plane);

}  // namespace drycut::interp
