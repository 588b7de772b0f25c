#pragma once
// The reference point of a turning tool under G41/G42 (docs/controller-state.md, "Turning tools
// under G41/G42"). The compensation computes the path of the cutting edge centre S; the machine
// moves so that S is on it, and the lengths it adds are measured to the tool tip P. So the
// reference point the axes carry runs on the S path moved by P - S (CompensationRequest::
// reference_shift), a constant vector while the edge stays active.
//
// The offset of a contour moved by a constant vector is the offset of the contour moved by it,
// so this stage moves the PROGRAMMED elements on their way into the compensation; the
// compensation itself (corners, intersections, bottlenecks) is unchanged:
// - while compensated, every element is moved by its block's shift;
// - the selection block (approach) starts where the tool is and ends moved: the shift is taken
//   up along the approach, as the compensation itself is;
// - the deselection block (retract, G40) starts moved and ends at its programmed point;
// - a shift that changes while active (another D) is taken up by the next straight block.
#include "interp/path_element.hpp"

namespace drycut::interp {

class EdgeReferenceShift {
 public:
  // Moves a motion element as above (other elements pass unchanged).
  void apply(PathElement& element);

 private:
  geometry::Vec3 current_ = geometry::Vec3::Zero();  // shift at the end of the last motion
};

}  // namespace drycut::interp
