// `$` system variables the program writes and the interpreter models: tool data $TC_DP3
// (length), $TC_DP6 (radius) and $TC_DPNT (number of teeth) of tool t, edge d, and the tool's
// name $TC_TP2[t]; settable frames $P_UIFR[n] (whole, from a
// frame function, or by component $P_UIFR[n, X, TR]; effective when next selected), the active
// settable frame $P_IFRAME (whole or by component, at once) and the programmable frame
// $P_PFRAME (whole or by component, at once) — frame_components.hpp. Other frame writes
// ($P_BFRAME, chained frame expressions) warn. Other writes were kept by the
// loader (later reads see them) and change nothing drycut times.
#include "interp/interpreter.hpp"
#include "interp/interpreter_block.hpp"
#include "parser/system_variables.hpp"

#include <cctype>
#include <cstdlib>

namespace drycut::interp {

using detail::kNotModelled;

void Interpreter::apply_system_writes(const parser::Block& block) {
  for (const parser::SystemWrite& w : block.system_writes) {
    const SourceLocation where{block.file ? *block.file : std::string(), block.line, w.column};
    // $TC_DP<n> and $TC_DPNT; the OEM and monitoring data ($TC_DPC<n>, $TC_DPH ...) are kept by
    // the loader only.
    const bool edge_parameter = w.name.rfind("$TC_DP", 0) == 0 &&
                                (w.name == "$TC_DPNT" || (w.name.size() > 6 && std::isdigit(static_cast<unsigned char>(w.name[6]))));
    if (edge_parameter && w.indices.size() == 2 && w.indices[0].is_number() && w.indices[1].is_number() &&
        w.value.is_number()) {
      const int parameter = std::atoi(w.name.c_str() + 6);
      // Indices no int holds are outside the table like any other (and their cast undefined).
      auto index = [](double v) { return v > -2147483648.0 && v < 2147483648.0 ? static_cast<int>(v) : -1; };
      const int t = index(w.indices[0].number), d = index(w.indices[1].number);
      // $TC_DPNT: number of teeth, the factor of the tooth feed G95 FZ.
      const bool written = w.name == "$TC_DPNT" ? tools_.set_edge_teeth(t, d, w.value.number)
                                                : tools_.set_edge_parameter(parameter, t, d, w.value.number);
      if (!written)
        diagnostics_.warn(kNotModelled, w.name + ": index outside the tool table's range", where, block.text);
      continue;
    }
    if (w.name == "$TC_TP2" && w.indices.size() == 1 && w.indices[0].is_number() && w.value.is_text()) {
      const double t = w.indices[0].number;
      if (!(t >= 1 && t <= 2147483647.0) || !tools_.set_tool_name(static_cast<int>(t), w.value.text))
        diagnostics_.warn(kNotModelled, w.name + ": index outside the tool table's range", where, block.text);
      continue;
    }
    if (write_frame_variable(block, w)) continue;
    // SD42940 / SD42950: where the tool lengths act from the next block on (tool_length_vector).
    // Values drycut does not model (a negative SD42940, whose sign changes the turning tools'
    // assignment) keep the last and are said once.
    if ((w.name == "$SC_TOOL_LENGTH_CONST" || w.name == "$SC_TOOL_LENGTH_TYPE") && w.value.is_number()) {
      const double v = w.value.number;
      const bool length_const = w.name == "$SC_TOOL_LENGTH_CONST";
      const bool known = length_const ? (v == 0 || v == 17 || v == 18 || v == 19) : (v == 0 || v == 1 || v == 2);
      if (known) (length_const ? tool_length_const_ : tool_length_type_) = static_cast<int>(v);
      else if (warned_.insert(w.name).second)
        diagnostics_.warn(kNotModelled, w.name + " = " + parser::number_to_text(v) + " not modelled: the last value stays",
                          where, block.text);
      continue;
    }
    // The override a synchronized action would set (Function Manual Synchronized Actions, $AC_OVR
    // path and $AA_OVR axis override, reset each IPO cycle): drycut plans at 100 %, as for OVR.
    if ((w.name == "$AC_OVR" || w.name == "$AA_OVR") && warned_.insert(w.name).second) {
      diagnostics_.warn(kNotModelled, w.name + " written (drycut plans at 100 % override)", where, block.text);
      continue;
    }
    // Any other frame ($P_BFRAME, $P_UBFR, $P_CHBFR[n], $P_SETFRAME ...: drycut has no basic or
    // system frames) or form (a component of $P_PFRAME): said once per name.
    if (!parser::is_frame_variable_name(w.name) || !warned_.insert(w.name).second) continue;
    const bool kept = w.name == "$P_UIFR" || w.name == "$P_PFRAME" || w.name == "$P_IFRAME";
    diagnostics_.warn(kNotModelled,
                      w.name + (kept ? " written in a form drycut does not compute: the frame stays as it was"
                                     : " written: drycut keeps no basic or system frames; the path stays without it"),
                      where, block.text);
  }
}

bool Interpreter::write_frame_variable(const parser::Block& block, const parser::SystemWrite& w) {
  const bool settable = w.name == "$P_UIFR";
  // $P_IFRAME: the active settable frame, in force at once (the table entry stays as it is).
  const bool active = w.name == "$P_IFRAME";
  if (!settable && !active && w.name != "$P_PFRAME") return false;
  const size_t first = settable ? 1 : 0;  // $P_UIFR[n, ...]: n first
  if (w.indices.size() != first && w.indices.size() != first + 2) return false;
  int n = 0;
  if (settable) {
    if (!w.indices[0].is_number() || !(w.indices[0].number >= 0 && w.indices[0].number < kSettableFrames)) return false;
    n = static_cast<int>(w.indices[0].number);
  }
  FrameComponents components = settable ? settable_components_[static_cast<size_t>(n)]
                               : active ? active_settable_components_
                                        : FrameComponents{};
  if (w.indices.size() == first + 2) {  // [.., axis, component] = value
    if (!w.value.is_number()) return false;
    if (!settable && !active) return write_programmable_component(w, first);
    const int axis = detail::axis_index(w.indices[first].text);
    const std::string& component = w.indices[first + 1].text;
    const bool length = component == "TR" || component == "FI";
    // A frame copied whole ($P_UIFR[2]=$P_UIFR[1] reads as a matrix) is split into translation,
    // rotation and scale where it is one, so that a component can be set (as _FR[X,TR]= does).
    if (components.composed()) {
      const std::optional<FrameComponents> split = FrameComponents::of_product(components.frame());
      if (!split) return false;
      components = *split;
    }
    if (axis < 0 || !components.set(axis, component, w.value.number * (length ? geometry_unit() : 1.0))) return false;
  } else {
    if (w.value.kind != parser::ValueKind::Frame) return false;
    // An empty description is the null frame (a FRAME variable never assigned, CTRANS()).
    const std::string error = w.value.text.empty() ? std::string() : components.assign(w.value.text, geometry_unit());
    if (w.value.text.empty()) components = FrameComponents{};
    if (!error.empty()) {
      const SourceLocation where{block.file ? *block.file : std::string(), block.line, w.column};
      diagnostics_.warn(kNotModelled, w.name + ": " + error + " (the frame stays as it was)", where, block.text);
      return true;
    }
  }
  const Frame frame = components.frame();
  if (!frame.invertible()) return false;
  if (settable) {
    settable_components_[static_cast<size_t>(n)] = components;
    set_settable_frame(n, frame);
  } else if (active) {
    active_settable_components_ = components;
    state_.frames.set_settable(frame);
  } else {
    set_programmable_frame(frame);
  }
  return true;
}

bool Interpreter::write_programmable_component(const parser::SystemWrite& w, size_t first) {
  // The programmable frame is kept as a matrix, not as the components TRANS, ROT, SCALE and
  // MIRROR built: TR (the outermost offset) can always be written; RT, SC and MI only while the
  // frame is a pure translation (a mirror and a rotation cannot be told apart from the matrix,
  // MIRROR X0 Y0 is a half turn); FI is not kept for it. Anything else: false (warned).
  const int axis = detail::axis_index(w.indices[first].text);
  const std::string& component = w.indices[first + 1].text;
  const Frame& now = state_.frames.programmable();
  if (axis < 0) return false;
  if (component == "TR") {
    Eigen::Vector3d offset = now.offset();
    offset[axis] = w.value.number * geometry_unit();
    set_programmable_frame(Frame::affine(now.linear(), offset));
    return true;
  }
  if (component == "FI" || !now.is_pure_translation()) return false;
  FrameComponents components;  // a pure translation: its offset is all there is
  components.translation = now.offset();
  if (!components.set(axis, component, w.value.number)) return false;
  const Frame frame = components.frame();
  if (!frame.invertible()) return false;
  set_programmable_frame(frame);
  return true;
}

}  // namespace drycut::interp
