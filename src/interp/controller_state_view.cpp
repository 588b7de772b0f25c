#include "interp/controller_state_view.hpp"

#include <cmath>
#include <cstdlib>

#include "parser/command_table.hpp"

namespace drycut::interp {
namespace {

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
    case MotionMode::ArcTangent: return 15;
  }
  return 0;
}

int code_index(int code) {
  int group = 0, index = 0;
  return parser::g_group_of_code(code, group, index) ? index : 0;
}

}  // namespace

std::optional<double> InterpreterStateView::g_group_index(int group) const {
  const ModalState& s = interpreter_.state();
  switch (group) {
    case 1: return motion_index(s.motion);
    case 6: return s.plane == PlaneSelect::G17 ? 1 : s.plane == PlaneSelect::G18 ? 2 : 3;
    case 7: return s.compensation == CompensationSide::None ? 1 : s.compensation == CompensationSide::Left ? 2 : 3;
    case 8: return code_index(std::atoi(s.work_offset.c_str() + 1));
    case 13: return s.inch ? (s.inch_feed ? 3 : 1) : 2;  // G70 G71 G700 G710 (G710 reads as G71)
    case 14: return s.absolute ? 1 : 2;
    case 15: return s.feed_per_rev ? 3 : 2;
    case 18: return s.intersection_corners ? 2 : 1;
    default: return std::nullopt;
  }
}

std::optional<double> InterpreterStateView::axis_position(std::span<const Value> indices) const {
  if (indices.size() != 1) return std::nullopt;
  const std::string& axis = indices[0].text;
  if (axis.empty()) return std::nullopt;
  for (int k = 0; k < 3; ++k)
    if (axis[0] == profile_.axes[static_cast<size_t>(k)].name[0]) return interpreter_.position()[k];
  return std::nullopt;
}

std::optional<double> InterpreterStateView::tool_datum(int parameter, std::span<const Value> indices) const {
  // $TC_DPn[t, d]: edge d of tool t; DP3 = length 1, DP6 = radius.
  if (indices.size() != 2 || !indices[0].is_number() || !indices[1].is_number()) return std::nullopt;
  const machine::Tool* tool = profile_.find_tool(static_cast<int>(indices[0].number));
  if (!tool) return 0.0;
  for (const auto& e : tool->edges)
    if (e.d == static_cast<int>(indices[1].number)) return parameter == 6 ? e.radius_mm : parameter == 3 ? e.length_mm : 0.0;
  return 0.0;
}

std::optional<Value> InterpreterStateView::read_system_variable(std::string_view n, std::span<const Value> indices) const {
  const ModalState& s = interpreter_.state();
  auto number = [](std::optional<double> v) { return v ? std::optional<Value>(Value(*v)) : std::nullopt; };
  if (n == "$P_GG" && indices.size() == 1 && indices[0].is_number())
    return number(g_group_index(static_cast<int>(indices[0].number)));
  if (n == "$P_EP" || n == "$AA_IM" || n == "$AA_IW" || n == "$AA_IEN" || n == "$VA_IM") return number(axis_position(indices));
  if (n == "$P_F") return Value(s.feed);
  if (n == "$P_S" || n == "$AA_S") return Value(s.spindle_rpm);
  if (n == "$P_TOOL") return Value(static_cast<double>(s.edge));
  if (n == "$P_TOOLR" || n == "$P_AD[6]") return Value(s.tool_radius_mm);
  if (n == "$P_TOOLNO" || n == "$TC_MPP6" || n == "$AC_TOOLNO") {
    const char* t = s.active_tool ? s.active_tool->c_str() : "0";
    char* end = nullptr;
    const double v = std::strtod(t, &end);
    return Value(end && *end == '\0' ? v : 0.0);
  }
  if (n == "$P_TOOLP") {
    const char* t = s.prepared_tool ? s.prepared_tool->c_str() : "0";
    return Value(std::atof(t));
  }
  if (n == "$TC_DP3") return number(tool_datum(3, indices));
  if (n == "$TC_DP6") return number(tool_datum(6, indices));
  if (n == "$TC_GETT" && indices.size() == 1) {
    if (const machine::Tool* t = profile_.find_tool(indices[0].text)) return Value(static_cast<double>(t->number));
    return Value(-1.0);
  }
  if (n == "$AC_TIME" || n == "$AC_PATHN") return Value(0.0);
  return std::nullopt;
}

}  // namespace drycut::interp
