// Kinematic transformations drycut does not model (TRANSMIT, TRACYL, TRAANG, TRAORI) and the
// software limit switches (docs/axes.md "Kinematic transformations"). While one is
// active the programmed X/Y/Z are the axes of the transformation (TRANSMIT's Y on a lathe is a
// virtual axis, TRACYL's the developed cylinder surface), not machine axes: comparing them with
// the machine axes' limits would raise 10720 where the control moves. drycut skips the check for
// the geometry axes with a one-time warning; TRAFOOF switches the transformation off and puts the
// geometry axes where the machine axes are (below).
#include <cmath>

#include "interp/interpreter.hpp"
#include "interp/interpreter_block.hpp"

namespace drycut::interp {

bool Interpreter::apply_transformation_command(const parser::CommandWord& c) {
  const std::string& n = c.name;
  if (n == "TRAFOOF") {
    // The geometry axes are the machine axes again, where the transformation left them (M1:
    // TRANSMIT and TRACYL move the virtual ordinate with C and X, not with a Y slide): after
    // TRANSMIT X is the tool's distance from the turning axis, after both Y is where it was when
    // the transformation began. The programmed X/Y of the transformed plane are not positions.
    if (unmodelled_transformation_ == "TRANSMIT") position_.x() = std::hypot(position_.x(), position_.y());
    if (unmodelled_transformation_ == "TRANSMIT" || unmodelled_transformation_ == "TRACYL")
      position_.y() = transformation_start_.y();
    unmodelled_transformation_.clear();
    return true;
  }
  if (n != "TRANSMIT" && n != "TRACYL" && n != "TRAANG" && n != "TRAORI") return false;
  // The loader has warned that the transformation itself is not modelled.
  if (unmodelled_transformation_.empty()) transformation_start_ = position_;
  unmodelled_transformation_ = n;
  return true;
}

bool Interpreter::limits_checked(const BlockContext& ctx) {
  if (part_swivelled_) {
    // A swivelled table turns the part: where the linear axes stand depends on the table's pivot
    // ($TC_CARR kinematics), which the profile does not give; the rotated frame alone would map
    // the programmed point onto the wrong machine axes (frame Y onto machine Z after A-90).
    if (block_frame(ctx).linear().isIdentity(1e-12)) {
      part_swivelled_ = false;
    } else {
      warn_once(ctx, "software limit switches not checked while a swivel turns the part (the linear axes' "
                     "positions depend on the table's pivot, which the profile does not give)", 0);
      return false;
    }
  }
  if (unmodelled_transformation_.empty()) return true;
  warn_once(ctx, "software limit switches not checked while " + unmodelled_transformation_ +
                     " is active (the programmed axes are not the machine axes)", 0);
  return false;
}

}  // namespace drycut::interp
