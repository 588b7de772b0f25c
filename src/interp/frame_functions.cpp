#include "interp/frame_functions.hpp"

#include <array>
#include <optional>

#include "interp/frame_chain.hpp"

namespace drycut::interp {
namespace {

int axis_of(const parser::Argument& a) {
  const auto* s = std::get_if<std::string>(&a);
  if (!s) return -1;
  if (*s == "X") return 0;
  if (*s == "Y") return 1;
  if (*s == "Z") return 2;
  return -1;
}

}  // namespace

bool is_frame_function(std::string_view name) {
  return name == "CTRANS" || name == "CROT" || name == "CSCALE" || name == "CMIRROR";
}

FrameFunctionResult frame_function(std::string_view name, const std::vector<parser::Argument>& args) {
  FrameFunctionResult result;
  const bool pairs = name != "CMIRROR";
  FrameInstructionWords words;
  for (size_t i = 0; i < args.size(); i += pairs ? 2 : 1) {
    const int axis = axis_of(args[i]);
    if (axis < 0) {
      result.error = std::string(name) + ": argument " + std::to_string(i + 1) + " must be a geometry axis X, Y or Z";
      return result;
    }
    double value = 0.0;
    if (pairs) {
      const double* v = i + 1 < args.size() ? std::get_if<double>(&args[i + 1]) : nullptr;
      if (!v) {
        result.error = std::string(name) + ": axis " + "XYZ"[axis] + " needs a value";
        return result;
      }
      value = *v;
    }
    words.axes[static_cast<size_t>(axis)] = value;
  }
  if (name == "CTRANS") {
    result.frame = instruction_frame(FrameInstruction::Trans, words, 2);
  } else if (name == "CROT") {
    result.frame = instruction_frame(FrameInstruction::Rot, words, 2);
  } else if (name == "CSCALE") {
    result.frame = instruction_frame(FrameInstruction::Scale, words, 2);
    if (!result.frame.invertible()) result.error = "CSCALE: a scale factor 0 leaves no inverse";
  } else if (name == "CMIRROR") {
    result.frame = instruction_frame(FrameInstruction::Mirror, words, 2);
  } else {
    result.error = std::string(name) + " is not a frame function";
  }
  return result;
}

}  // namespace drycut::interp
