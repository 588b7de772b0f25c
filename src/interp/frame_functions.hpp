#pragma once
// The frame functions of the NC language, for frame assignments such as
//   $P_PFRAME = CTRANS(X, 10, Y, 20) : CROT(Z, 30)      $P_UIFR[1] = CTRANS(X, 100)
// (docs/controller-state.md, "Frames"): CTRANS(axis, offset, ...), CROT(axis, angle, ...),
// CSCALE(axis, factor, ...), CMIRROR(axis, ...). The `:` chaining operator is Frame::then.
// Lengths are taken as mm (the caller converts inch values); angles in degrees; CROT with
// several axes is an RPY rotation like ROT.
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "interp/frame.hpp"
#include "parser/block.hpp"

namespace drycut::interp {

struct FrameFunctionResult {
  Frame frame;
  std::string error;  // empty = ok; otherwise what is wrong with the arguments
  bool ok() const { return error.empty(); }
};

bool is_frame_function(std::string_view name);
FrameFunctionResult frame_function(std::string_view name, const std::vector<parser::Argument>& args);

}  // namespace drycut::interp
