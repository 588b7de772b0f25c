// Where the machine is under tool radius compensation: the reference point of a turning tool
// (edge position, P - S) and the actual position $AA_IM/$AA_IW reads while G41/G42 is active
// (docs/controller-state.md, "Turning tools under G41/G42" and "Actual positions under G41/G42").
#include "interp/cutting_edge_position.hpp"
#include "interp/interpreter.hpp"

namespace drycut::interp {

using Eigen::Vector3d;

Vector3d Interpreter::edge_reference_shift(const CompensationRequest& request) const {
  const ToolOffsets& o = tools_.offsets();
  const Eigen::Vector2d tip = tip_from_edge_centre(o.type, o.edge_position) * o.radius_mm;
  if (tip.isZero()) return Vector3d::Zero();
  // The position number is defined in the plane's axes (a plane a frame tilted: its axes).
  if (request.tilted) return tip[0] * request.tilted_first + tip[1] * request.tilted_normal.cross(request.tilted_first);
  const PlaneIndices plane = state_.plane_indices();
  return tip[0] * Vector3d::Unit(plane.first) + tip[1] * Vector3d::Unit(plane.second);
}

void Interpreter::note_compensated_end(const PathElement& element) {
  const CompensationRequest& c = element.compensation;
  last_motion_compensated_ = c.side != CompensationSide::None;
  if (!last_motion_compensated_) {
    compensated_offset_ = Vector3d::Zero();
    return;
  }
  // The tool centre stands perpendicular to the block's end direction in the plane, at the
  // radius (plus OFFN) on the compensation side, as the compensation puts the end of a block it
  // cannot yet join to the next (drycut's reading of the read's preprocessing stop). A block
  // without motion in the plane (an infeed) keeps the offset of the block before.
  const Vector3d n = c.tilted ? c.tilted_normal : Vector3d::Unit(c.plane_normal_axis);
  const Vector3d t = element.curve->at(element.curve->length()).tangent;
  const Vector3d in_plane = t - n * n.dot(t);
  if (in_plane.norm() < 1e-9) return;
  const double d = c.side == CompensationSide::Left ? c.radius_mm : -c.radius_mm;
  compensated_offset_ = d * n.cross(in_plane.normalized()) + c.reference_shift;
}

Vector3d Interpreter::actual_position() const {
  return last_motion_compensated_ ? Vector3d(position_ + compensated_offset_) : position_;
}

}  // namespace drycut::interp
