// Kinematic transformations drycut does not model (TRANSMIT, TRACYL, TRAANG, TRAORI) and the
// software limit switches (docs/axes.md "Kinematic transformations"). While one is
// active the programmed X/Y/Z are the axes of the transformation (TRANSMIT's Y on a lathe is a
// virtual axis, TRACYL's the developed cylinder surface), not machine axes: comparing them with
// the machine axes' limits would raise 10720 where the control moves. drycut skips the check for
// the geometry axes with a one-time warning; TRAFOOF switches the transformation off.
#include "interp/interpreter.hpp"
#include "interp/interpreter_block.hpp"

namespace drycut::interp {

bool Interpreter::apply_transformation_command(const parser::CommandWord& c) {
  const std::string& n = c.name;
  if (n == "TRAFOOF") {
    unmodelled_transformation_.clear();
    return true;
  }
  if (n != "TRANSMIT" && n != "TRACYL" && n != "TRAANG" && n != "TRAORI") return false;
  // The loader has warned that the transformation itself is not modelled.
  unmodelled_transformation_ = n;
  return true;
}

bool Interpreter::limits_checked(const BlockContext& ctx) {
  if (unmodelled_transformation_.empty()) return true;
  warn_once(ctx, "software limit switches not checked while " + unmodelled_transformation_ +
                     " is active (the programmed axes are not the machine axes)", 0);
  return false;
}

}  // namespace drycut::interp
