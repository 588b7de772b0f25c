#include "machine/profile_md_names.hpp"

#include <array>
#include <utility>

#include <nlohmann/json.hpp>

namespace drycut::machine {
namespace {

// Last key component (without unit) -> datum; axis keys and others share one table because the
// component names never collide. docs/machine-profile.md is the reference for every row.
constexpr std::array<std::pair<std::string_view, std::string_view>, 70> kNames{{
    {"min", "MD36100 POS_LIMIT_MINUS"},
    {"max", "MD36110 POS_LIMIT_PLUS"},
    {"max_velocity", "MD32000 MAX_AX_VELO"},
    {"max_accel", "MD32300 MAX_AX_ACCEL"},
    {"max_jerk", "MD32431 MAX_AX_JERK"},
    {"transition_jerk", "MD32432 PATH_TRANS_JERK_LIM"},
    {"pos_velocity", "MD32060 POS_AX_VELO"},
    {"rotary", "MD30300 IS_ROT_AX"},
    {"modulo", "MD30310 ROT_IS_MODULO"},
    {"modulo_range", "MD30330 MODULO_RANGE"},
    {"misc_function_mask", "MD30455 MISC_FUNCTION_MASK"},
    {"ipo_cycle", "MD10050 SYSCLOCK_CYCLE_TIME x MD10070 IPO_SYSCLOCK_TIME_RATIO"},
    {"max_accel_ovl_factor", "MD32310 MAX_ACCEL_OVL_FACTOR"},
    {"max_path_jerk", "MD20600 MAX_PATH_JERK"},
    {"soft_accel_factor", "MD32433 SOFT_ACCEL_FACTOR"},
    {"curv_effect_on_path_accel", "MD20602 CURV_EFFECT_ON_PATH_ACCEL"},
    {"lookahead_blocks", "- (bounded by MD28060 MM_IPO_BUFFER_SIZE)"},
    {"short_block_factor", "- (short-block rule)"},
    {"g0_accel_factor", "MD32434 G00_ACCEL_FACTOR"},
    {"g0_jerk_factor", "MD32435 G00_JERK_FACTOR"},
    {"tool_change_time", "- (machine specific)"},
    {"spindle_ramp_time", "- (from MD35200/35210)"},
    {"max_spindle_speed_rpm", "MD35100 SPIND_VELO_LIMIT"},
    {"master_spindle", "MD20090 SPIND_DEF_MASTER_SPIND"},
    {"spindle_posctrl_velo_rpm", "MD35300 SPIND_POSCTRL_VELO"},
    {"spindle_posctrl_accel_rev_s2", "MD35210 GEAR_STEP_POSCTRL_ACCEL"},
    {"spindle_speedctrl_accel_rev_s2", "MD35200 GEAR_STEP_SPEEDCTRL_ACCEL"},
    {"spindle_on_speed_at_ipo_start", "MD35500 SPIND_ON_SPEED_AT_IPO_START"},
    {"spindle_des_velo_tol", "MD35150 SPIND_DES_VELO_TOL"},
    {"reset_gcodes", "MD20150 GCODE_RESET_VALUES"},
    {"work_offsets", "$P_UIFR (settable frames)"},
    {"work_offset_rotations", "$P_UIFR rotations"},
    {"start_position", "-"},
    {"circle_error_const", "MD21000 CIRCLE_ERROR_CONST"},
    {"circle_error_factor", "MD21010 CIRCLE_ERROR_FACTOR"},
    {"cutcom_decel_limit", "SD42528 CUTCOM_DECEL_LIMIT"},
    {"cutcom_corner_limit", "MD20210 CUTCOM_CORNER_LIMIT"},
    {"cutcom_curve_insert_limit", "MD20230 CUTCOM_CURVE_INSERT_LIMIT"},
    {"cubic_spline_blocks", "MD20160 CUBIC_SPLINE_BLOCKS"},
    {"cubic_spline_global", "- (drycut option)"},
    {"cutcom_maxnum_check_blocks", "MD20240 CUTCOM_MAXNUM_CHECK_BLOCKS"},
    {"cutcom_maxnum_dummy_blocks", "MD20250 CUTCOM_MAXNUM_DUMMY_BLOCKS"},
    {"tool_change_mode", "MD22550 TOOL_CHANGE_MODE"},
    {"tool_change_m_code", "MD22560 TOOL_CHANGE_M_CODE"},
    {"cutting_edge_default", "MD20270 CUTTING_EDGE_DEFAULT"},
    {"tool_table_complete", "- (drycut)"},
    {"tool_length_const", "SD42940 TOOL_LENGTH_CONST"},
    {"tool_length_type", "SD42950 TOOL_LENGTH_TYPE"},
    {"swivel_kinematics", "$TC_CARR23"},
    {"diameter_ax_def", "MD20100 DIAMETER_AX_DEF"},
    {"base_unit", "MD10240 SCALING_SYSTEM_IS_METRIC"},
    {"radius", "$TC_DP6 (tool radius)"},
    {"length", "$TC_DP3 (tool length 1)"},
    {"tools", "tool offsets $TC_DP"},
    {"compress_pos_tol", "MD33100 COMPRESS_POS_TOL"},
    {"compress_block_path_limit", "MD20170 COMPRESS_BLOCK_PATH_LIMIT"},
    {"compress_velo_tol", "MD20172 COMPRESS_VELO_TOL"},
    {"compress_contur_tol", "SD42475 COMPRESS_CONTUR_TOL"},
    {"compressor_mode", "MD20482 COMPRESSOR_MODE"},
    {"crit_spline_angle", "SD42470 CRIT_SPLINE_ANGLE"},
    {"max_blocks_per_span", "- (FB1: COMPON/COMPCURV join up to 10 blocks)"},
    {"flush_points", "- (drycut: compressor run window)"},
    {"smoothing_mode", "MD20480 SMOOTHING_MODE"},
    {"smooth_contur_tol", "SD42465 SMOOTH_CONTUR_TOL"},
    {"smooth_ori_tol", "SD42466 SMOOTH_ORI_TOL"},
    {"ignore_ovl_factor_for_adis", "MD20490 IGNORE_OVL_FACTOR_FOR_ADIS"},
    {"g0_tolerance_factor", "MD20560 G0_TOLERANCE_FACTOR"},
    {"mm_max_axispoly_per_block", "MD28520 MM_MAX_AXISPOLY_PER_BLOCK"},
    {"max_block_share", "- (drycut: share of a block the corner rounding may take)"},
    {"adis_max_reduction", "- (PGA: ADIS shortened by up to 36 % on short blocks)"},
}};

// Unit suffixes written by profile_to_json, longest first.
constexpr std::array<std::string_view, 10> kUnitSuffixes{
    "_mm_min", "_deg_min", "_m_s2", "_deg_s2", "_m_s3", "_deg_s3", "_mm", "_deg", "_ms", "_s"};

void flatten(const nlohmann::ordered_json& node, const std::string& path,
             std::vector<std::pair<std::string, std::string>>& rows) {
  if (node.is_object() && !node.empty()) {
    for (auto it = node.begin(); it != node.end(); ++it)
      flatten(it.value(), path.empty() ? it.key() : path + "." + it.key(), rows);
    return;
  }
  if (node.is_array() && !node.empty() && node.front().is_object()) {
    for (size_t i = 0; i < node.size(); ++i) flatten(node[i], path + "[" + std::to_string(i) + "]", rows);
    return;
  }
  rows.emplace_back(path, node.dump());
}

// The datum of one key component, with or without its unit suffix; empty when none.
std::string_view name_of_component(std::string_view last) {
  for (auto [stem, md] : kNames)
    if (last == stem) return md;
  for (std::string_view suffix : kUnitSuffixes) {
    if (last.size() > suffix.size() && last.ends_with(suffix)) {
      const std::string_view stem = last.substr(0, last.size() - suffix.size());
      for (auto [name, md] : kNames)
        if (stem == name) return md;
    }
  }
  return {};
}

}  // namespace

std::vector<std::pair<std::string, std::string>> flatten_profile_json(const std::string& json_text) {
  std::vector<std::pair<std::string, std::string>> rows;
  flatten(nlohmann::ordered_json::parse(json_text), "", rows);
  return rows;
}

std::string md_name_of(std::string_view key_path) {
  if (key_path.starts_with("machine_data.")) return std::string(key_path.substr(13));
  // The innermost key component that names a datum ("program.work_offsets_mm.G54" -> work_offsets).
  while (!key_path.empty()) {
    const size_t dot = key_path.rfind('.');
    std::string_view last = key_path.substr(dot == std::string_view::npos ? 0 : dot + 1);
    last = last.substr(0, last.find('['));
    if (auto md = name_of_component(last); !md.empty()) return std::string(md);
    if (dot == std::string_view::npos) break;
    key_path = key_path.substr(0, dot);
  }
  return "-";
}

}  // namespace drycut::machine
