// Frame system variables a program reads (Job Planning and Function Manual K2, "Frames":
// current frames and the frame table): whole frames ($P_PFRAME, $P_UIFR[n], $P_IFRAME,
// $P_ACTFRAME ...) as a FRAME value, and their components [axis, TR|FI|RT|SC|MI] as numbers.
//
// drycut keeps the settable frames (by components), the programmable frame and their product;
// it has no basic frames and no system frames, so every other frame variable ($P_BFRAME,
// $P_UBFR, $P_CHBFR[n], $P_NCBFRAME[n], $P_SETFRAME, $P_TOOLFRAME, $P_CYCFRAME ...: names of the
// $P_ family that end in FRAME or FR) reads as the null frame, as an unconfigured frame does on
// the control. Components of a frame drycut keeps only as a matrix (the programmable frame, the
// active or total frame) are taken from it: TR its translation (the outermost component), FI 0,
// SC the length of each column, RT the RPY angles of what remains (Rz·Ry·Rx, as ROT), MI 1 where
// a single mirror makes the determinant negative on that axis' column sign.
#include <cmath>

#include "interp/controller_state_view.hpp"
#include "interp/frame_components.hpp"
#include "interp/interpreter_block.hpp"
#include "parser/system_variables.hpp"

namespace drycut::interp {
namespace {

using parser::Value;

// Indices that select the frame itself (before [axis, component]).
size_t frame_index_count(std::string_view n) {
  return n == "$P_UIFR" || n == "$P_CHBFR" || n == "$P_NCBFR" || n == "$P_CHBFRAME" || n == "$P_NCBFRAME" ? 1 : 0;
}

std::optional<double> component_of_matrix(const Frame& frame, int axis, std::string_view c, double unit) {
  const Eigen::Matrix3d& l = frame.linear();
  if (c == "TR") return frame.offset()[axis] / unit;
  if (c == "FI") return 0.0;
  Eigen::Vector3d scale(l.col(0).norm(), l.col(1).norm(), l.col(2).norm());
  if (c == "SC") return scale[axis];
  Eigen::Matrix3d r = l;
  for (int i = 0; i < 3; ++i) r.col(i) /= scale[i];
  if (c == "MI") return r.determinant() < 0 && r(axis, axis) < 0 ? 1.0 : 0.0;
  if (c == "RT" && r.determinant() > 0) return rpy_degrees(r)[axis];
  return std::nullopt;
}

std::optional<double> component_of(const FrameComponents& f, int axis, std::string_view c, double unit) {
  if (c == "TR") return f.translation[axis] / unit;
  if (c == "FI") return f.fine[axis] / unit;
  if (c == "RT") return f.rotation_deg[axis];
  if (c == "SC") return f.scale[axis];
  if (c == "MI") return f.mirror[static_cast<size_t>(axis)] ? 1.0 : 0.0;
  return std::nullopt;
}

// A FRAME variable's text as components (empty text: the null frame); false where it is no frame
// drycut can read.
bool read_frame_text(std::string_view text, double unit, FrameComponents& c) {
  return text.empty() || c.assign(text, unit).empty();
}

}  // namespace

std::optional<Value> InterpreterStateView::frame_variable(std::string_view n, std::span<const Value> indices) const {
  if (!parser::is_frame_variable_name(n)) return std::nullopt;
  const size_t first = frame_index_count(n);
  if (indices.size() != first && indices.size() != first + 2) return std::nullopt;
  const ModalState& s = interpreter_.state();
  const double unit = s.inch ? 25.4 : 1.0;
  int settable = -1;
  Frame frame;  // the null frame for every frame drycut does not keep
  if (n == "$P_UIFR") {
    const Value& i = indices[0];
    if (!i.is_number() || !(i.number >= 0 && i.number < kSettableFrames) || i.number != std::trunc(i.number))
      return std::nullopt;
    settable = static_cast<int>(i.number);
    frame = interpreter_.settable_frame(settable);
  } else if (n == "$P_PFRAME") {
    frame = s.frames.programmable();
  } else if (n == "$P_IFRAME") {
    frame = s.frames.settable();
  } else if (n == "$P_ACTFRAME") {
    frame = s.frames.total(false);
  }
  if (indices.size() == first) return frame_value(frame, unit);
  const Value& axis_word = indices[first];
  const Value& component = indices[first + 1];
  const int axis = detail::axis_index(axis_word.text);
  if (axis < 0) return std::nullopt;
  if (settable >= 0) {
    const FrameComponents& c = interpreter_.settable_components(settable);
    if (!c.composed()) {
      const std::optional<double> v = component_of(c, axis, component.text, unit);
      return v ? std::optional<Value>(Value(*v)) : std::nullopt;
    }
  }
  if (auto v = component_of_matrix(frame, axis, component.text, unit)) return Value(*v);
  return std::nullopt;
}

std::optional<double> InterpreterStateView::frame_component(std::string_view text, std::string_view axis_name,
                                                            std::string_view component) const {
  // A FRAME variable's component (_FR[X,TR]): its text computed as a frame ($P_UIFR[n]=_FR would
  // compute the same), the component as a $P_UIFR[n, X, TR] read gives it.
  const double unit = interpreter_.state().inch ? 25.4 : 1.0;
  const int axis = detail::axis_index(axis_name);
  FrameComponents c;
  if (axis < 0 || !read_frame_text(text, unit, c)) return std::nullopt;
  return c.composed() ? component_of_matrix(c.frame(), axis, component, unit) : component_of(c, axis, component, unit);
}

std::optional<std::string> InterpreterStateView::frame_with_component(std::string_view text, std::string_view axis_name,
                                                                      std::string_view component, double value) const {
  // _FR[X,TR]=v: the frame by its components (a product such as a whole $P_UIFR[n] read is split
  // into translation, rotation and scale where it is one), the component set, back as text.
  const double unit = interpreter_.state().inch ? 25.4 : 1.0;
  const int axis = detail::axis_index(axis_name);
  FrameComponents c;
  if (axis < 0 || !read_frame_text(text, unit, c)) return std::nullopt;
  if (c.composed()) {
    const std::optional<FrameComponents> split = FrameComponents::of_product(c.frame());
    if (!split) return std::nullopt;
    c = *split;
  }
  const bool length = component == "TR" || component == "FI";
  if (!c.set(axis, component, length ? value * unit : value)) return std::nullopt;
  return c.text(unit);
}

}  // namespace drycut::interp
