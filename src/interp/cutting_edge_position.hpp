#pragma once
// The cutting edge position of a turning tool ($TC_DP2; Programming Manual Fundamentals, "Tool
// compensation memory"; Function Manual W1, "Cutting edge position and cut direction";
// docs/controller-state.md "Turning tools under G41/G42"). A turning tool's lengths are measured
// to the theoretical tool tip P, where the tangents to the nose circle parallel to the plane's
// axes meet; the radius compensation guides the nose centre S. The position number says where P
// lies from S, in the working plane's axes (abscissa, ordinate; G18: Z, X):
//   1 (+,+)  2 (-,+)  3 (-,-)  4 (+,-)  5 (+,0)  6 (0,+)  7 (-,0)  8 (0,-)
// each component r long (P of position 3 is r behind S on both axes, r·sqrt(2) away).
// 9 (and 0, not given): S itself is the reference point.
#include <Eigen/Core>

namespace drycut::interp {

// P - S in units of the nose radius along (abscissa, ordinate); zero for positions 0, 9 and any
// tool that is not a turning tool (type 500..599).
inline Eigen::Vector2d tip_from_edge_centre(int tool_type, int edge_position) {
  if (tool_type < 500 || tool_type > 599) return Eigen::Vector2d::Zero();
  switch (edge_position) {
    case 1: return {1.0, 1.0};
    case 2: return {-1.0, 1.0};
    case 3: return {-1.0, -1.0};
    case 4: return {1.0, -1.0};
    case 5: return {1.0, 0.0};
    case 6: return {0.0, 1.0};
    case 7: return {-1.0, 0.0};
    case 8: return {0.0, -1.0};
    default: return Eigen::Vector2d::Zero();
  }
}

}  // namespace drycut::interp
