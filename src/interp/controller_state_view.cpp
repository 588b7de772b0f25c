#include "interp/controller_state_view.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "interp/frame_components.hpp"
#include "interp/interpreter_block.hpp"

#include "parser/command_table.hpp"
#include "parser/expression_evaluator.hpp"

namespace drycut::interp {
namespace {
// tool_datum's parameter for $TC_DPNT (number of teeth): beyond the $TC_DPn numbers 1..25.
constexpr int kTeeth = 100;

using parser::Value;

// Internal numbers of the G group 1 codes beyond G0..G3 (PGA Fundamentals, list of G groups).
int motion_index(MotionMode m) {
  switch (m) {
    case MotionMode::Rapid: return 1;
    case MotionMode::Linear: return 2;
    case MotionMode::ArcCw: return 3;
    case MotionMode::ArcCcw: return 4;
    case MotionMode::ArcThroughPoint: return 5;
    case MotionMode::ASpline: return 6;
    case MotionMode::BSpline: return 7;
    case MotionMode::CSpline: return 8;
    case MotionMode::Polynomial: return 9;         // POLY
    case MotionMode::ArcTangent: return 15;
    case MotionMode::Thread: return 10;            // G33
    case MotionMode::Tapping: return 11;           // G331
    case MotionMode::TappingRetract: return 12;    // G332
    case MotionMode::ThreadIncreasing: return 16;  // G34
    case MotionMode::ThreadDecreasing: return 17;  // G35
  }
  return 0;
}

// T number of a tool selection ("5" -> 5; a named tool -> its number in the table; none -> 0).
double tool_number(const ToolState& tools, const std::optional<std::string>& id) {
  if (!id) return 0.0;
  char* end = nullptr;
  const double v = std::strtod(id->c_str(), &end);
  if (end && *end == '\0') return v;
  const machine::Tool* tool = tools.find(*id);
  return tool ? tool->number : 0.0;
}

int code_index(int code) {
  int group = 0, index = 0;
  return parser::g_group_of_code(code, group, index) ? index : 0;
}

}  // namespace

std::optional<Value> InterpreterStateView::tool_presence(std::string_view n, std::span<const Value> indices) const {
  if (indices.size() != 1 || !indices[0].is_number()) return std::nullopt;
  const machine::Tool* tool = interpreter_.tools().find(parser::number_to_text(indices[0].number));
  // $P_TOOLEXIST[t]: is tool t in the tool table; $TC_TP2[t]: its name (empty when none).
  if (n == "$P_TOOLEXIST") return Value(tool ? 1.0 : 0.0);
  if (n == "$TC_TP2") return Value::of_text(tool ? tool->name : std::string());
  if (n == "$TC_TP1") return Value(tool ? static_cast<double>(tool->duplo) : 0.0);  // duplo number
  // $TC_TP8[t], the tool status bits (Function Manual Tool Management: bit 0 active, bit 1
  // enabled, bit 2 disabled, bit 3 measured, ...): a tool of the run's table is enabled (a dry
  // run knows no locks), the one in the spindle also active. Macros check the enabled bit
  // before a change and stop with their own alarm when it is 0.
  if (n == "$TC_TP8") {
    if (!tool) return Value(0.0);
    const auto& active = interpreter_.tools().active_tool();
    const machine::Tool* in_spindle = active ? interpreter_.tools().find(*active) : nullptr;
    return Value(in_spindle == tool ? 3.0 : 2.0);
  }
  return std::nullopt;
}

std::optional<double> InterpreterStateView::g_group_index(int group) const {
  const ModalState& s = interpreter_.state();
  switch (group) {
    case 1: return motion_index(s.motion);
    case 6: return s.plane == PlaneSelect::G17 ? 1 : s.plane == PlaneSelect::G18 ? 2 : 3;
    case 7: return s.compensation == CompensationSide::None ? 1 : s.compensation == CompensationSide::Left ? 2 : 3;
    case 8: return code_index(std::atoi(s.work_offset.c_str() + 1));
    case 13: return s.inch ? (s.feed_in_geometry_unit ? 3 : 1) : (s.feed_in_geometry_unit ? 4 : 2);  // G70 G71 G700 G710
    case 14: return s.absolute ? 1 : 2;
    case 15: return s.feed_mode == FeedMode::InverseTime ? 1 : s.feed_mode == FeedMode::PerRevolution ? 3 : 2;
    case 10:  // G60 G64 G641 G642 G643 G644 G645
      switch (s.transition) {
        case TransitionMode::ExactStop: return 1;
        case TransitionMode::Continuous: return 2;
        case TransitionMode::SmoothDistance: return 3;
        case TransitionMode::SmoothTolerance: return s.smoothing.code >= 642 && s.smoothing.code <= 645 ? s.smoothing.code - 638 : 4;
      }
      return std::nullopt;
    case 12: return s.exact_stop_window - 600;  // G601 G602 G603
    case 16: return static_cast<double>(s.contour_feed) + 1;  // CFC CFTCP CFIN
    case 17: return s.contour_approach ? 2 : 1;                // NORM KONT (KONTT, KONTC: modelled as KONT)
    case 18: return s.intersection_corners ? 2 : 1;
    case 23: return s.collision_detection ? 2 : 1;             // CDOF CDON (CDOF2: modelled as CDOF)
    case 29: return static_cast<double>(s.diameter.channel) + 1;  // DIAMOF DIAMON DIAM90 DIAMCYCOF
    case 21: return s.accel == AccelProfile::Soft ? 2 : 1;  // BRISK SOFT (DRIVE)
    case 30: return static_cast<double>(s.compressor) + 1;   // COMPOF COMPON COMPCURV COMPCAD COMPSURF
    case 59: return static_cast<double>(s.dynamic_group) + 1;  // DYNNORM DYNPOS DYNROUGH DYNSEMIFIN DYNFINISH DYNPREC
    default: return std::nullopt;
  }
}

std::optional<int> InterpreterStateView::spindle_index(std::span<const Value> indices) const {
  // Spindle n of $P_S[n], $AA_S[n], $P_SDIR[n]; without an index (or [0]) the master spindle.
  // The index may be the spindle's axis, SP<n> (from SPI(n) or S<n>).
  double k = indices.size() == 1 && indices[0].is_number() ? indices[0].number : 0.0;
  if (indices.size() == 1 && !indices[0].is_number()) {
    const std::string& axis = indices[0].text;
    k = detail::is_spindle_axis_name(axis) && axis.size() <= 4 ? std::stod(axis.substr(2)) : -1.0;
  }
  if (!(k >= 0 && k <= 99 && k == std::trunc(k))) return std::nullopt;
  return static_cast<int>(k);
}

std::optional<Value> InterpreterStateView::spindle_speed(bool actual, std::span<const Value> indices) const {
  const auto spindle = spindle_index(indices);
  if (!spindle) return std::nullopt;
  return Value(actual ? interpreter_.spindle_speed_on_ramp(*spindle) : interpreter_.programmed_spindle_speed(*spindle));
}

std::optional<double> InterpreterStateView::axis_position(std::span<const Value> indices, bool workpiece, bool actual) const {
  if (indices.size() != 1) return std::nullopt;
  const std::string& axis = indices[0].text;
  if (axis.empty()) return std::nullopt;
  if (const int i = interpreter_.extra_axes().index(axis); i >= 0)
    return actual ? interpreter_.extra_axis_actual_position(static_cast<size_t>(i))
                  : interpreter_.extra_axes().position(static_cast<size_t>(i));
  for (int k = 0; k < 3; ++k)
    if (axis[0] == profile_.axes[static_cast<size_t>(k)].name[0])
      return workpiece ? interpreter_.workpiece_position(actual)[k]
                       : actual ? interpreter_.actual_position()[k] : interpreter_.position()[k];
  return std::nullopt;
}

bool InterpreterStateView::changes_while_polled(std::string_view n, std::span<const parser::Value> indices) const {
  // The actual position of an axis on its way from POSA (Job Planning: $AA_IM, $AA_IW read the
  // actual value; reading them in the part program waits for the main run).
  if (!parser::is_actual_position_name(n) || indices.size() != 1 || indices[0].text.empty()) return false;
  return interpreter_.extra_axes().moving_at(indices[0].text, interpreter_.nominal_time_s()) != nullptr;
}

std::optional<double> InterpreterStateView::tool_datum(int parameter, std::span<const Value> indices) const {
  // parameter: n of $TC_DPn, or kTeeth for $TC_DPNT.
  // $TC_DPn[t, d]: edge d of tool t; DP1 type, DP2 edge position, DP3..5 lengths 1..3, DP6
  // radius, DP12..15 their wear, DP21..23 base lengths.
  if (indices.size() != 2 || !indices[0].is_number() || !indices[1].is_number()) return std::nullopt;
  const machine::Tool* tool = interpreter_.tools().find(parser::number_to_text(indices[0].number));
  if (!tool) return 0.0;
  for (const auto& e : tool->edges) {
    if (e.d != indices[1].number) continue;
    switch (parameter) {
      case 1: return static_cast<double>(e.type);
      case 2: return static_cast<double>(e.edge_position);
      case 3: return e.length_mm - e.length_wear_mm;
      case 4: return e.length2_mm - e.length2_wear_mm;
      case 5: return e.length3_mm - e.length3_wear_mm;
      case 6: return e.radius_mm - e.radius_wear_mm;
      case 12: return e.length_wear_mm;
      case 13: return e.length2_wear_mm;
      case 14: return e.length3_wear_mm;
      case 15: return e.radius_wear_mm;
      case 21:
      case 22:
      case 23: return e.base_mm[static_cast<size_t>(parameter - 21)];
      case kTeeth: return static_cast<double>(e.teeth);
      default: return 0.0;
    }
  }
  return 0.0;
}

Value InterpreterStateView::frame_value(const Frame& frame, double unit) {
  // CFRAME(linear row by row, translation in the program's unit): read back exactly by
  // FrameComponents (frame_components.hpp) when the variable is written to a frame again.
  std::string text(kWholeFrameFunction);
  char buf[32];
  for (int k = 0; k < 12; ++k) {
    const double v = k < 9 ? frame.linear()(k / 3, k % 3) : frame.offset()[k - 9] / unit;
    std::snprintf(buf, sizeof buf, "%.17g", v);
    text += k == 0 ? '(' : ',';
    text += buf;
  }
  text += ')';
  Value f = Value::of_frame();
  f.text = std::move(text);
  return f;
}

int InterpreterStateView::settable_frame_number(const std::string& work_offset) {
  if (work_offset.size() < 2 || work_offset[0] != 'G') return 0;
  const int g = std::atoi(work_offset.c_str() + 1);
  if (g >= 54 && g <= 57) return g - 53;
  if (g >= 505 && g <= 599) return g - 500;
  return 0;  // G500 (and G53/G153, which suppress without selecting)
}

// The active tool and the tool table: $P_TOOL (edge), $P_TOOLR, $P_TOOLL[1..3], $P_TOOLNO,
// $P_TOOLP, $P_AD[n], $TC_DPNT, $TC_DPn and $TC_GETT.
std::optional<Value> InterpreterStateView::tool_variable(std::string_view n, std::span<const Value> indices) const {
  auto number = [](std::optional<double> v) { return v ? std::optional<Value>(Value(*v)) : std::nullopt; };
  const ToolState& tools = interpreter_.tools();
  if (n == "$P_TOOL") return Value(static_cast<double>(tools.edge()));
  // Radius and lengths in the unit of tool data: inch under G700, the base system under G70/G71.
  const double unit = interpreter_.tool_data_unit();
  if (n == "$P_TOOLR") return Value(tools.offsets().radius_mm / unit);
  if (n == "$P_TOOLL") {
    // $P_TOOLL[1..3]: the active edge's lengths 1, 2, 3 (geometry + wear + base); no index: length 1.
    const double k = indices.size() == 1 && indices[0].is_number() ? indices[0].number : 1.0;
    const ToolOffsets& o = tools.offsets();
    return Value((k == 1 ? o.length_mm : k == 2 ? o.length2_mm : k == 3 ? o.length3_mm : 0.0) / unit);
  }
  if (n == "$P_TOOLNO" || n == "$AC_TOOLNO") return Value(tool_number(tools, tools.active_tool()));
  if (n == "$P_TOOLP") return Value(tool_number(tools, tools.programmed_tool()));
  if (n == "$P_AD" && indices.size() == 1 && indices[0].is_number()) {
    // $P_AD[n]: parameter n of the active cutting edge, as $TC_DPn[active tool, active D] (the
    // ones tool_datum keeps; the others read 0 here). No edge active: 0.
    if (!tools.has_tool() || tools.edge() <= 0) return Value(0.0);
    const Value edge_indices[2] = {Value(tool_number(tools, tools.active_tool())), Value(static_cast<double>(tools.edge()))};
    const double k = indices[0].number;
    return number(tool_datum(k >= 1 && k <= 25 ? static_cast<int>(k) : 0, edge_indices));
  }
  if (n == "$TC_DPNT") return number(tool_datum(kTeeth, indices));
  if (n.size() > 6 && n.substr(0, 6) == "$TC_DP" && std::isdigit(static_cast<unsigned char>(n[6]))) {
    // The parameters drycut keeps: DP1..6, DP12..15, DP21..23 (the others as any unknown datum).
    int k = 0;
    for (char c : n.substr(6)) k = std::isdigit(static_cast<unsigned char>(c)) && k < 100 ? k * 10 + (c - '0') : 1000;
    if ((k >= 1 && k <= 6) || (k >= 12 && k <= 15) || (k >= 21 && k <= 23)) return number(tool_datum(k, indices));
  }
  if (n == "$TC_GETT" && (indices.size() == 1 || indices.size() == 2)) {
    const double duplo = indices.size() == 2 && indices[1].is_number() ? indices[1].number : 0.0;
    const machine::Tool* t = duplo == 0                     ? tools.find(indices[0].text)
                             : duplo >= 1 && duplo <= 32000 ? tools.find_sister(indices[0].text, static_cast<int>(duplo))
                                                            : nullptr;
    return Value(t ? static_cast<double>(t->number) : -1.0);
  }
  return std::nullopt;
}

std::optional<Value> InterpreterStateView::read_system_variable(std::string_view n, std::span<const Value> indices) const {
  const ModalState& s = interpreter_.state();
  auto number = [](std::optional<double> v) { return v ? std::optional<Value>(Value(*v)) : std::nullopt; };
  if (n == "$P_GG" && indices.size() == 1 && indices[0].is_number()) {
    const double g = indices[0].number;  // beyond 0..99 no group (and no undefined int cast)
    return number(g_group_index(g >= 0 && g <= 99 ? static_cast<int>(g) : -1));
  }
  // Workpiece coordinates ($P_EP programmed end point, $AA_IW/$VA_IW actual, $AA_IEN settable
  // zero system, taken as the workpiece system) and machine coordinates ($AA_IM/$VA_IM, $AA_IB
  // basic system: the machine here). In a dry run the actual position is where the path puts the
  // tool: the programmed point, or under G41/G42 the compensated one (Interpreter::actual_position).
  if (n == "$P_EP") return number(axis_position(indices, true, false));
  if (n == "$AA_IW" || n == "$VA_IW" || n == "$AA_IEN") return number(axis_position(indices, true, true));
  if (n == "$AA_IM" || n == "$VA_IM" || n == "$AA_IB") return number(axis_position(indices, false, true));
  if (n == "$P_F") return Value(s.feed);
  // drycut's contour recording (contour_recording.hpp): the count and [element, column].
  if (n == "$DRYCUT_CONTOUR_N") return Value(static_cast<double>(interpreter_.recorded_contour().size()));
  if (n == "$DRYCUT_CONTOUR" && indices.size() == 2 && indices[0].is_number() && indices[1].is_number()) {
    const ContourRecorder& contour = interpreter_.recorded_contour();
    const double i = indices[0].number, k = indices[1].number;
    if (i >= 0 && i < static_cast<double>(contour.size()) && i == std::trunc(i) && k >= 0 &&
        k < ContourRecorder::kColumns && k == std::trunc(k))
      return number(contour.value(static_cast<size_t>(i), static_cast<int>(k), s.plane_indices()));
  }
  // Whether the profile's machine_data gives $TC_CARR<k>[1] of the swivel data record: CYCLE800
  // retracts and swivels only with data the profile has (docs/cycles.md "CYCLE800").
  if (n == "$DRYCUT_SWIVEL_DATUM" && indices.size() == 1 && indices[0].is_number())
    return Value(profile_.machine_data.count("$TC_CARR" + parser::as_text(indices[0]) + "[1]") ? 1.0 : 0.0);
  if (n == "$P_S" || n == "$AA_S") return spindle_speed(n == "$AA_S", indices);
  // The direction of spindle n (Job Planning, system variables: $P_SDIR the programmed one,
  // $AC_SDIR the current one; in a dry run the same): 3 = M3, 4 = M4, 5 = stopped.
  if (n == "$P_SDIR" || n == "$AC_SDIR") {
    if (const auto k = spindle_index(indices)) return Value(static_cast<double>(interpreter_.spindle_direction(*k)));
    return std::nullopt;
  }
  // drycut runs one channel: channel 1 (macros index per-channel GUD arrays with it).
  if (n == "$P_CHANNO" && indices.empty()) return Value(1.0);
  // The master spindle's number (MD20090, SETMS(n)).
  if (n == "$P_MSNUM" || n == "$AC_MSNUM") return Value(static_cast<double>(interpreter_.master_spindle()));
  if (auto v = tool_variable(n, indices)) return v;
  if (n == "$AC_TIME" || n == "$AC_PATHN") return Value(0.0);
  if (auto v = tool_presence(n, indices)) return v;
  // The geometry axes of the plane (Job Planning, "$P_AXN1..3"): abscissa, ordinate, applicate.
  if ((n == "$P_AXN1" || n == "$P_AXN2" || n == "$P_AXN3") && indices.empty()) {
    const PlaneIndices plane = s.plane_indices();
    const int i = n.back() == '1' ? plane.first : n.back() == '2' ? plane.second : plane.normal;
    return Value::of_axis(profile_.axes[static_cast<size_t>(i)].name);
  }
  // Every axis of a dry run is referenced and has its measuring system active: macros check
  // them before they move ($AA_REF[ax], $AA_ENC_ACTIVE[ax]).
  if ((n == "$AA_REF" || n == "$AA_ENC_ACTIVE") && indices.size() == 1) return Value(1.0);
  // The number of the active settable frame (Job Planning, "$P_UIFRNUM"): G500 0, G54..G57 1..4,
  // G505..G599 5..99.
  if (n == "$P_UIFRNUM") return Value(static_cast<double>(settable_frame_number(s.work_offset)));
  // A measuring input (MEAS/MEAW) is taken as having switched: a dry run has no part to touch,
  // and a probing macro checks the flag before it goes on (the control would stop it otherwise).
  if (n == "$AC_MEA") return Value(1.0);
  // The run drycut simulates is a plain automatic run: no block search ($P_SEARCH), no program
  // test ($P_ISTEST), no dry-run feed ($P_DRYRUN), not the control's own simulation ($P_SIM).
  // Macros read them to skip moves in those modes (Job Planning, system variables list).
  if (n == "$P_SEARCH" || n == "$P_ISTEST" || n == "$P_DRYRUN" || n == "$P_SIM") return Value(0.0);
  // Frames, whole (to be kept in a FRAME variable and written back: $P_PFRAME=SAVED) or by component.
  return frame_variable(n, indices);
}

}  // namespace drycut::interp
