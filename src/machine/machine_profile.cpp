#include "machine/machine_profile.hpp"

#include <algorithm>
#include <array>
#include <fstream>
#include <regex>
#include <sstream>

#include <nlohmann/json.hpp>

#include "default_profile_json.hpp"
#include "machine/profile_axes.hpp"
#include "machine/profile_compressor.hpp"
#include "machine/profile_object_reader.hpp"

namespace drycut::machine {
namespace {

using nlohmann::json;
void read_path(const json& node, MachineProfile& p) {
  ProfileObjectReader r(node, "path");
  bool jerk_given = false;
  if (auto v = r.quantity("ipo_cycle", Dimension::Time))
    p.ipo_cycle_s = require_positive(*v, r.key_path("ipo_cycle"));
  if (auto v = r.number("max_accel_ovl_factor"))
    p.max_accel_ovl_factor = require_range(*v, 1.0, 10.0, r.key_path("max_accel_ovl_factor"));
  if (auto v = r.quantity("max_path_jerk", Dimension::Jerk)) {
    p.path_jerk_mm_s3 = require_positive(*v, r.key_path("max_path_jerk"));
    jerk_given = true;
  }
  if (auto v = r.number("soft_accel_factor"))
    p.soft_accel_factor = require_positive(*v, r.key_path("soft_accel_factor"));
  if (auto v = r.number("curv_effect_on_path_accel"))
    p.curv_effect_on_path_accel = require_range(*v, 0.0, 0.95, r.key_path("curv_effect_on_path_accel"));
  if (auto v = r.integer("lookahead_blocks")) {
    if (*v < 1 || *v > 100000) r.fail("lookahead_blocks", "must be in [1, 100000]");
    p.lookahead_blocks = static_cast<int>(*v);
  }
  if (auto v = r.number("short_block_factor"))
    p.short_block_factor = require_range(*v, 1e-6, 10.0, r.key_path("short_block_factor"));
  if (auto v = r.number("g0_accel_factor"))
    p.g0_accel_factor = require_positive(*v, r.key_path("g0_accel_factor"));
  if (auto v = r.number("g0_jerk_factor"))
    p.g0_jerk_factor = require_positive(*v, r.key_path("g0_jerk_factor"));
  if (auto v = r.quantity("tool_change_time", Dimension::Time))
    p.tool_change_time_s = require_non_negative(*v, r.key_path("tool_change_time"));
  if (auto v = r.quantity("spindle_ramp_time", Dimension::Time))
    p.spindle_ramp_time_s = require_non_negative(*v, r.key_path("spindle_ramp_time"));
  if (auto v = r.integer("master_spindle")) {
    if (*v < 1 || *v > 99) r.fail("master_spindle", "must be in [1, 99]");
    p.master_spindle = static_cast<int>(*v);
  }
  if (auto v = r.number("max_spindle_speed_rpm"))
    p.max_spindle_speed_rpm = require_positive(*v, r.key_path("max_spindle_speed_rpm"));
  if (auto v = r.number("spindle_posctrl_velo_rpm"))
    p.spindle_posctrl_velo_rpm = require_positive(*v, r.key_path("spindle_posctrl_velo_rpm"));
  if (auto v = r.number("spindle_posctrl_accel_rev_s2"))
    p.spindle_posctrl_accel_rev_s2 = require_positive(*v, r.key_path("spindle_posctrl_accel_rev_s2"));
  if (auto v = r.number("spindle_speedctrl_accel_rev_s2"))
    p.spindle_speedctrl_accel_rev_s2 = require_positive(*v, r.key_path("spindle_speedctrl_accel_rev_s2"));
  if (auto v = r.integer("spindle_on_speed_at_ipo_start")) {
    if (*v < 0 || *v > 2) r.fail("spindle_on_speed_at_ipo_start", "must be 0, 1 or 2");
    p.spindle_on_speed_at_ipo_start = static_cast<int>(*v);
  }
  if (auto v = r.number("spindle_des_velo_tol"))
    p.spindle_des_velo_tol = require_range(*v, 0.0, 1.0, r.key_path("spindle_des_velo_tol"));
  r.reject_unknown_keys();
  if (!jerk_given) {
    // No path jerk given: the smallest axis jerk is the safe stand-in.
    p.path_jerk_mm_s3 = std::min({p.axes[0].max_jerk_mm_s3, p.axes[1].max_jerk_mm_s3, p.axes[2].max_jerk_mm_s3});
  }
}

// Settable frames by name: G500 ($P_UIFR[0]), G54..G57 and G505..G599, each [x, y, z].
void read_settable_frames(ProfileObjectReader& r, const char* key, std::map<std::string, Eigen::Vector3d>& out) {
  const json* node = r.child(key);
  if (!node) return;
  ProfileObjectReader o(*node, r.key_path(key));
  if (!node->is_object()) r.fail(key, "must be an object: frame name -> [x, y, z]");
  static const std::regex kFrameName("G500|G5[4-7]|G5(0[5-9]|[1-9][0-9])");
  for (auto it = node->begin(); it != node->end(); ++it) {
    if (!std::regex_match(it.key(), kFrameName))
      o.fail(it.key(), "not a settable work offset (G500, G54..G57, G505..G599)");
    const json& v = it.value();
    if (!v.is_array() || v.size() != 3 || !v[0].is_number() || !v[1].is_number() || !v[2].is_number())
      o.fail(it.key(), "must be an array of 3 numbers [x, y, z]");
    out[it.key()] = Eigen::Vector3d(v[0].get<double>(), v[1].get<double>(), v[2].get<double>());
  }
}

// MD22550, MD22560, MD20270, drycut's switch for an incomplete tool table, MD10240.
void read_tool_change_data(ProfileObjectReader& r, MachineProfile& p) {
  if (auto v = r.integer("tool_change_mode")) {
    if (*v != 0 && *v != 1) r.fail("tool_change_mode", "must be 0 (T changes) or 1 (M function changes)");
    p.tool_change_mode = static_cast<int>(*v);
  }
  if (auto v = r.integer("tool_change_m_code")) {
    if (*v < 0 || *v > 99999) r.fail("tool_change_m_code", "must be an M number 0..99999");
    p.tool_change_m_code = static_cast<int>(*v);
  }
  if (auto v = r.integer("cutting_edge_default")) {
    if (*v < -2 || *v > 32000) r.fail("cutting_edge_default", "must be -2, -1, 0 or an edge number 1..32000");
    p.cutting_edge_default = static_cast<int>(*v);
  }
  if (auto v = r.boolean("tool_table_complete")) p.tool_table_complete = *v;
  if (auto v = r.integer("tool_length_const")) {
    if (*v != 0 && *v != 17 && *v != 18 && *v != 19)
      r.fail("tool_length_const", "must be 0 (lengths follow the plane) or 17, 18, 19 (SD42940)");
    p.tool_length_const = static_cast<int>(*v);
  }
  if (auto v = r.integer("tool_length_type")) {
    if (*v < 0 || *v > 2) r.fail("tool_length_type", "must be 0 (by tool type), 1 (as milling tools) or 2 (as turning tools) (SD42950)");
    p.tool_length_type = static_cast<int>(*v);
  }
  if (auto v = r.string("swivel_kinematics")) {
    if (*v != "none" && *v != "table" && *v != "head")
      r.fail("swivel_kinematics", "must be \"none\", \"table\" or \"head\" ($TC_CARR23 T/P)");
    p.swivel_kinematics = *v;
  }
  if (auto v = r.string("diameter_ax_def")) {
    const bool geometry_axis = std::any_of(p.axes.begin(), p.axes.end(), [&](const AxisData& a) { return a.name == *v; });
    if (!v->empty() && !geometry_axis) r.fail("diameter_ax_def", "must name one of the path axes X, Y, Z or be empty");
    p.diameter_axis = *v;
  }
  if (auto v = r.string("base_unit")) {
    if (*v != "mm" && *v != "inch") r.fail("base_unit", "must be \"mm\" or \"inch\"");
    p.base_unit_inch = *v == "inch";
  }
}

void read_program(const json& node, MachineProfile& p) {
  ProfileObjectReader r(node, "program");
  if (const json* codes = r.child("reset_gcodes")) {
    if (!codes->is_array()) r.fail("reset_gcodes", "must be an array of strings");
    p.reset_gcodes.clear();
    for (const auto& c : *codes) {
      if (!c.is_string() || c.get<std::string>().empty())
        r.fail("reset_gcodes", "must be an array of non-empty strings");
      p.reset_gcodes.push_back(c.get<std::string>());
    }
  }
  read_settable_frames(r, "work_offsets_mm", p.work_offsets);
  read_settable_frames(r, "work_offset_rotations_deg", p.work_offset_rotations_deg);
  if (auto v = r.vector3("start_position", Dimension::Length)) p.start_position = *v;
  if (auto v = r.quantity("circle_error_const", Dimension::Length))
    p.circle_error_const_mm = require_positive(*v, r.key_path("circle_error_const"));
  if (auto v = r.number("circle_error_factor"))
    p.circle_error_factor = require_non_negative(*v, r.key_path("circle_error_factor"));
  if (auto v = r.number("cutcom_decel_limit"))
    p.cutcom_decel_limit = require_range(*v, 0.0, 1.0, r.key_path("cutcom_decel_limit"));
  if (auto v = r.number("cutcom_corner_limit_deg"))
    p.cutcom_corner_limit_deg = require_range(*v, 0.0, 180.0, r.key_path("cutcom_corner_limit_deg"));
  if (auto v = r.number("cutcom_curve_insert_limit_deg"))
    p.cutcom_curve_insert_limit_deg = require_range(*v, 0.0, 180.0, r.key_path("cutcom_curve_insert_limit_deg"));
  auto positive_int = [&](const char* key, int& field) {
    if (auto v = r.integer(key)) {
      if (*v < 1 || *v > 1000000) r.fail(key, "must be in [1, 1000000]");
      field = static_cast<int>(*v);
    }
  };
  positive_int("cubic_spline_blocks", p.cubic_spline_blocks);
  if (auto v = r.boolean("cubic_spline_global")) p.cubic_spline_global = *v;
  positive_int("cutcom_maxnum_check_blocks", p.cutcom_maxnum_check_blocks);
  positive_int("cutcom_maxnum_dummy_blocks", p.cutcom_maxnum_dummy_blocks);
  read_tool_change_data(r, p);
  r.reject_unknown_keys();
}

ToolEdge read_edge(const json& node, const std::string& path) {
  ProfileObjectReader r(node, path);
  ToolEdge e;
  auto d = r.integer("d");
  if (!d) r.fail("d", "missing");
  if (*d < 1 || *d > 12) r.fail("d", "must be in [1, 12]");
  e.d = static_cast<int>(*d);
  if (auto v = r.quantity("radius", Dimension::Length)) e.radius_mm = require_non_negative(*v, r.key_path("radius"));
  if (auto v = r.quantity("length", Dimension::Length)) e.length_mm = *v;
  if (auto n = r.integer("teeth")) {
    if (*n < 0 || *n > 32000) r.fail("teeth", "must be in [0, 32000]");
    e.teeth = static_cast<int>(*n);
  }
  if (auto n = r.integer("type")) {
    if (*n < 0 || *n > 999) r.fail("type", "must be in [0, 999] ($TC_DP1)");
    e.type = static_cast<int>(*n);
  }
  if (auto v = r.quantity("length2", Dimension::Length)) e.length2_mm = *v;
  if (auto v = r.quantity("length3", Dimension::Length)) e.length3_mm = *v;
  for (size_t i = 0; i < 3; ++i)
    if (auto v = r.quantity("base_length" + std::to_string(i + 1), Dimension::Length)) e.base_mm[i] = *v;
  if (auto n = r.integer("cutting_edge_position")) {
    if (*n < 0 || *n > 9) r.fail("cutting_edge_position", "must be in [0, 9] ($TC_DP2)");
    e.edge_position = static_cast<int>(*n);
  }
  r.reject_unknown_keys();
  return e;
}

void read_machine_data(const json& node, MachineProfile& p) {
  if (!node.is_object()) throw ProfileError("machine_data: must be an object of \"$NAME[index]\": number");
  for (auto it = node.begin(); it != node.end(); ++it) {
    if (it.key().empty() || it.key()[0] != '$')
      throw ProfileError("machine_data." + it.key() + ": names start with $ ($MN_..., $MA_...[X1], $A_IN[1])");
    if (it->is_boolean()) {
      p.machine_data[it.key()] = it->get<bool>() ? 1.0 : 0.0;
    } else if (it->is_number()) {
      p.machine_data[it.key()] = it->get<double>();
    } else {
      throw ProfileError("machine_data." + it.key() + ": must be a number");
    }
  }
}

void read_tools(const json& node, MachineProfile& p) {
  if (!node.is_array()) throw ProfileError("tools: must be an array");
  p.tools.clear();
  for (size_t i = 0; i < node.size(); ++i) {
    std::string path = "tools[" + std::to_string(i) + "]";
    ProfileObjectReader r(node[i], path);
    Tool t;
    auto name = r.string("name");
    if (!name || name->empty()) r.fail("name", "missing or empty");
    t.name = *name;
    auto number = r.integer("number");
    if (!number) r.fail("number", "missing");
    if (*number < 0 || *number > 32000) r.fail("number", "must be in [0, 32000]");
    t.number = static_cast<int>(*number);
    if (const json* edges = r.child("edges")) {
      if (!edges->is_array()) r.fail("edges", "must be an array");
      for (size_t k = 0; k < edges->size(); ++k)
        t.edges.push_back(read_edge((*edges)[k], r.key_path("edges") + "[" + std::to_string(k) + "]"));
    }
    // Sister tools share the name with their own duplo numbers ($TC_TP1); without "duplo" the
    // next free one.
    t.duplo = p.next_duplo(t.name);
    if (auto duplo = r.integer("duplo")) {
      if (*duplo < 1 || *duplo > 32000) r.fail("duplo", "must be in [1, 32000]");
      t.duplo = static_cast<int>(*duplo);
    }
    r.reject_unknown_keys();
    if (p.find_tool(t.name, t.duplo))
      r.fail("name", "tool '" + t.name + "' duplo " + std::to_string(t.duplo) + " defined twice");
    if (p.find_tool(t.number)) r.fail("number", "tool number " + std::to_string(t.number) + " defined twice");
    p.tools.push_back(std::move(t));
  }
}

}  // namespace

MachineProfile load_profile_json(const std::string& json_text, const std::string& origin) {
  json root;
  try {
    root = json::parse(json_text);
  } catch (const json::parse_error& e) {
    throw ProfileError(origin + ": not valid JSON: " + e.what());
  }
  try {
    MachineProfile p;
    ProfileObjectReader r(root, "");
    if (auto name = r.string("name")) p.name = *name;
    const json* axes = r.child("axes");
    if (!axes) r.fail("axes", "missing");
    read_axes(*axes, p);
    if (const json* path = r.child("path")) {
      read_path(*path, p);
    } else {
      read_path(json::object(), p);
    }
    if (const json* program = r.child("program")) read_program(*program, p);
    if (const json* compressor = r.child("compressor")) read_compressor(*compressor, p);
    if (const json* smoothing = r.child("smoothing")) read_smoothing(*smoothing, p);
    if (const json* tools = r.child("tools")) read_tools(*tools, p);
    if (const json* md = r.child("machine_data")) read_machine_data(*md, p);
    if (const json* groups = r.child("dynamic_groups")) read_dynamic_groups(*groups, p.dynamic_groups);
    r.reject_unknown_keys();
    return p;
  } catch (const ProfileError& e) {
    throw ProfileError(origin + ": " + e.what());
  }
}

std::vector<Tool> load_tools_json(const std::string& json_text, const std::string& origin) {
  json root;
  try {
    root = json::parse(json_text);
  } catch (const json::parse_error& e) {
    throw ProfileError(origin + ": not valid JSON: " + e.what());
  }
  try {
    MachineProfile p;
    if (root.is_object()) {
      // {"tools": [...]}: the profile's own key, so a profile's tool list can be cut out as is.
      ProfileObjectReader r(root, "");
      const json* tools = r.child("tools");
      if (!tools) r.fail("tools", "missing");
      r.reject_unknown_keys();
      read_tools(*tools, p);
    } else {
      read_tools(root, p);
    }
    return p.tools;
  } catch (const ProfileError& e) {
    throw ProfileError(origin + ": " + e.what());
  }
}

MachineProfile load_profile_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ProfileError(path + ": machine profile file cannot be opened");
  std::ostringstream text;
  text << in.rdbuf();
  return load_profile_json(text.str(), path);
}

const MachineProfile& default_profile() {
  // Parsed once; the embedded text is validated by the same loader as any user file.
  static const MachineProfile profile = load_profile_json(kDefaultProfileJson, "<embedded mcv1210.json>");
  return profile;
}

std::string profile_to_json(const MachineProfile& p) {
  json root;
  root["name"] = p.name;
  root["axes"] = axes_to_json(p);
  root["path"] = {{"ipo_cycle_ms", p.ipo_cycle_s * 1000.0},
                  {"max_accel_ovl_factor", p.max_accel_ovl_factor},
                  {"max_path_jerk_m_s3", p.path_jerk_mm_s3 / 1000.0},
                  {"soft_accel_factor", p.soft_accel_factor},
                  {"curv_effect_on_path_accel", p.curv_effect_on_path_accel},
                  {"lookahead_blocks", p.lookahead_blocks},
                  {"short_block_factor", p.short_block_factor},
                  {"g0_accel_factor", p.g0_accel_factor},
                  {"g0_jerk_factor", p.g0_jerk_factor},
                  {"tool_change_time_s", p.tool_change_time_s},
                  {"spindle_ramp_time_s", p.spindle_ramp_time_s},
                  {"max_spindle_speed_rpm", p.max_spindle_speed_rpm},
                  {"master_spindle", p.master_spindle},
                  {"spindle_posctrl_velo_rpm", p.spindle_posctrl_velo_rpm},
                  {"spindle_posctrl_accel_rev_s2", p.spindle_posctrl_accel_rev_s2},
                  {"spindle_speedctrl_accel_rev_s2", p.spindle_speedctrl_accel_rev_s2},
                  {"spindle_on_speed_at_ipo_start", p.spindle_on_speed_at_ipo_start},
                  {"spindle_des_velo_tol", p.spindle_des_velo_tol}};
  json offsets = json::object();
  for (const auto& [name, v] : p.work_offsets) offsets[name] = {v.x(), v.y(), v.z()};
  json rotations = json::object();
  for (const auto& [name, v] : p.work_offset_rotations_deg) rotations[name] = {v.x(), v.y(), v.z()};
  root["program"] = {{"reset_gcodes", p.reset_gcodes},
                     {"work_offsets_mm", offsets},
                     {"work_offset_rotations_deg", rotations},
                     {"start_position_mm", {p.start_position.x(), p.start_position.y(), p.start_position.z()}},
                     {"circle_error_const_mm", p.circle_error_const_mm},
                     {"circle_error_factor", p.circle_error_factor},
                     {"cutcom_decel_limit", p.cutcom_decel_limit},
                     {"cutcom_corner_limit_deg", p.cutcom_corner_limit_deg},
                     {"cutcom_curve_insert_limit_deg", p.cutcom_curve_insert_limit_deg},
                     {"cubic_spline_blocks", p.cubic_spline_blocks},
                     {"cubic_spline_global", p.cubic_spline_global},
                     {"cutcom_maxnum_check_blocks", p.cutcom_maxnum_check_blocks},
                     {"cutcom_maxnum_dummy_blocks", p.cutcom_maxnum_dummy_blocks},
                     {"tool_change_mode", p.tool_change_mode},
                     {"tool_change_m_code", p.tool_change_m_code},
                     {"cutting_edge_default", p.cutting_edge_default},
                     {"tool_table_complete", p.tool_table_complete},
                     {"tool_length_const", p.tool_length_const},
                     {"tool_length_type", p.tool_length_type},
                     {"swivel_kinematics", p.swivel_kinematics},
                     {"diameter_ax_def", p.diameter_axis},
                     {"base_unit", p.base_unit_inch ? "inch" : "mm"}};
  json tools = json::array();
  for (const auto& t : p.tools) {
    json edges = json::array();
    for (const auto& e : t.edges) {
      json edge{{"d", e.d}, {"radius_mm", e.radius_mm}, {"length_mm", e.length_mm}};
      if (e.teeth > 0) edge["teeth"] = e.teeth;
      if (e.type > 0) edge["type"] = e.type;
      if (e.length2_mm != 0) edge["length2_mm"] = e.length2_mm;
      if (e.length3_mm != 0) edge["length3_mm"] = e.length3_mm;
      for (size_t i = 0; i < 3; ++i)
        if (e.base_mm[i] != 0) edge["base_length" + std::to_string(i + 1) + "_mm"] = e.base_mm[i];
      if (e.edge_position != 0) edge["cutting_edge_position"] = e.edge_position;
      edges.push_back(edge);
    }
    json tool{{"name", t.name}, {"number", t.number}, {"edges", edges}};
    if (t.duplo != 1) tool["duplo"] = t.duplo;
    tools.push_back(tool);
  }
  root["compressor"] = compressor_to_json(p);
  root["smoothing"] = smoothing_to_json(p);
  root["tools"] = tools;
  if (!p.machine_data.empty()) root["machine_data"] = p.machine_data;
  if (auto groups = dynamic_groups_to_json(p.dynamic_groups); !groups.empty()) root["dynamic_groups"] = groups;
  return root.dump(2);
}

}  // namespace drycut::machine
