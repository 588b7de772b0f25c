#pragma once
// Machine data: everything a machine builder sets on the real control, as one profile shared by
// all programs of a machine. Units inside: mm, s, rad. The JSON form carries units in its keys
// (docs/machine-profile.md documents every field and why the default has its value).
#include <algorithm>
#include <array>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "machine/dynamic_groups.hpp"

namespace drycut::machine {

// One machine axis. A rotary axis keeps its values in degrees where the names say mm
// (positions, velocity, acceleration, jerk): the planner treats both as path units.
struct AxisData {
  std::string name;               // "X", "Y", "Z", "A", "C", "U" ...
  bool rotary = false;            // MD30300 IS_ROT_AX
  bool modulo = false;            // MD30310 ROT_IS_MODULO: positions wrap, DC/ACP/ACN choose the way
  double modulo_range = 360.0;    // MD30330 MODULO_RANGE (degrees)
  int misc_function_mask = 0;     // MD30455 MISC_FUNCTION_MASK: bit 2 = G90 on a modulo axis goes as DC
  double pos_velocity_mm_s = 10000.0 / 60.0;  // MD32060 POS_AX_VELO: POS/POSA feed without FA
  double min_mm = -1e9;           // software limit switches (alarm 10720 outside)
  double max_mm = 1e9;
  double max_velocity_mm_s = 0;   // MD32000 MAX_AX_VELO
  double max_accel_mm_s2 = 0;     // MD32300 MAX_AX_ACCEL
  double max_jerk_mm_s3 = 0;      // MD32431 MAX_AX_JERK
  double transition_jerk_mm_s3 = 0;  // MD32432 PATH_TRANS_JERK_LIM (SOFT, at block transitions); 0 = max_jerk
  double compress_pos_tol_mm = 0.1;  // MD33100 COMPRESS_POS_TOL: compressor deviation from the programmed points
  // G75 FP=1..4 / G74 targets in machine coordinates; empty / nullopt: not in the profile.
  std::vector<double> fix_points_mm;               // MD30600 FIX_POINT_POS[0..3]
  std::optional<double> reference_point_mm;        // MD34100 REFP_SET_POS[0]
};

// The NC block compressor COMPON/COMPCURV/COMPCAD (docs/compressor.md): channel machine and
// setting data, plus drycut's own choices (named as such).
struct CompressorData {
  double block_path_limit_mm = 20.0;     // MD20170 COMPRESS_BLOCK_PATH_LIMIT: longer blocks are not compressed
  double velo_tol_mm_s = 100.0 / 60.0;   // MD20172 COMPRESS_VELO_TOL: a larger F change breaks a run
  double contur_tol_mm = 0.05;           // SD42475 COMPRESS_CONTUR_TOL (COMPRESSOR_MODE units digit 1/3)
  int mode = 0;                          // MD20482 COMPRESSOR_MODE (units: tolerance set; hundreds: circles/G0)
  double crit_spline_angle_deg = 36.0;   // SD42470 CRIT_SPLINE_ANGLE: a sharper bend is a corner
  int max_blocks_per_span = 10;          // COMPON/COMPCURV: blocks one polynomial may join (FB1: "up to 10")
  int flush_points = 1000;               // drycut: a run is fitted and handed on every this many points
};

// Corner smoothing G641/G642/G643/G645 (docs/smoothing.md): channel machine and setting data,
// plus drycut's own choices (named as such). The per-axis tolerance is MD33100 (AxisData).
struct SmoothingData {
  // MD20480 SMOOTHING_MODE: units digit G643, tens digit G642/G645; 0 axis tolerances MD33100,
  // 1 contour tolerance SD42465, 2 orientation tolerance (geometry axes: MD33100 here),
  // 3 contour and orientation, 4 the distances ADIS/ADISPOS. Higher digits are not modelled.
  int mode = 0;
  double contur_tol_mm = 0.05;              // SD42465 SMOOTH_CONTUR_TOL
  double ori_tol_deg = 0.05;                // SD42466 SMOOTH_ORI_TOL (orientation: not modelled)
  bool ignore_ovl_factor = false;           // MD20490 IGNORE_OVL_FACTOR_FOR_ADIS
  double g0_tolerance_factor = 3.0;         // MD20560 G0_TOLERANCE_FACTOR (G0 blocks: tolerance × this)
  int max_axispoly_per_block = 3;           // MD28520 MM_MAX_AXISPOLY_PER_BLOCK (< 3: no G642..G645 rounding)
  double max_block_share = 0.5;             // drycut: the rounding takes at most this share of each neighbour
  double adis_max_reduction = 0.36;         // PGA: ADIS is shortened by up to 36 % on short blocks; more: as G64
};

struct ToolEdge {
  int d = 1;               // D number
  double radius_mm = 0;    // cutter radius (tool radius compensation): geometry + wear
  double length_mm = 0;    // length 1, geometry + wear: tool length compensation along the plane normal
  int teeth = 0;           // $TC_DPNT number of teeth (tooth feed G95 FZ); 0 = not known
  // The wear parts of the two ($TC_DP15, $TC_DP12) as the program wrote them (an imported tool
  // table already holds the sums).
  double radius_wear_mm = 0;
  double length_wear_mm = 0;
  // $TC_DP1 tool type (120 end mill, 500..599 turning tools ...; 0 not given: a milling tool).
  int type = 0;
  // Lengths 2 and 3 ($TC_DP4, $TC_DP5), geometry + wear ($TC_DP13, $TC_DP14; the program's wear
  // parts kept as for length 1). Which axis each length acts on depends on the tool type and the
  // plane (Function Manual W1, "Tool length compensation"; docs/controller-state.md).
  double length2_mm = 0;
  double length3_mm = 0;
  double length2_wear_mm = 0;
  double length3_wear_mm = 0;
  // $TC_DP21..23 base (adapter) lengths 1..3, added to lengths 1..3 for every tool type (W1,
  // "Basic length 1 to 3").
  std::array<double, 3> base_mm{0.0, 0.0, 0.0};
  // $TC_DP2 cutting edge position of a turning tool: 1..8 where the theoretical tip P lies from the
  // cutting edge centre S, 9 (or 0: not given) S is the reference point.
  int edge_position = 0;
};

struct Tool {
  std::string name;        // T="name" (case-sensitive)
  int number = 0;          // T<n>
  std::vector<ToolEdge> edges;
  int duplo = 1;           // $TC_TP1 duplo number: sister tools share the name, each its own duplo
};

// By name: the sister tool of the lowest duplo number (drycut's choice of the tool management's
// strategy: a dry run knows no wear or lock); duplo > 0: that sister tool only.
inline const Tool* find_sister_tool(const std::vector<Tool>& tools, const std::string& name, int duplo = 0) {
  const Tool* found = nullptr;
  for (const auto& t : tools)
    if (t.name == name && (duplo > 0 ? t.duplo == duplo : !found || t.duplo < found->duplo)) found = &t;
  return found;
}

struct MachineProfile {
  std::string name;
  std::array<AxisData, 3> axes;                 // X, Y, Z path axes
  // Further channel axes (rotary A/B/C, linear U/V/W ...), by name order: they move with the
  // path (synchronized axes) or as positioning axes (POS/POSA). docs/axes.md.
  std::vector<AxisData> extra_axes;

  // Interpolation and look-ahead.
  double ipo_cycle_s = 0.004;                   // MD10050 × MD10070
  double max_accel_ovl_factor = 1.2;            // MD32310
  double path_jerk_mm_s3 = 0;                   // MD20600 MAX_PATH_JERK
  double soft_accel_factor = 1.0;               // MD32433 SOFT_ACCEL_FACTOR
  double curv_effect_on_path_accel = 0.75;      // MD20602
  // DYNPOS ... DYNPREC as factors on the DYNNORM values above (machine/dynamic_groups.hpp).
  DynamicGroupTable dynamic_groups;
  int lookahead_blocks = 64;                    // effective look-ahead depth (MD28060 bound)
  double short_block_factor = 0.9;              // v <= factor * L / T_IPO
  double g0_accel_factor = 1.0;                 // MD32434 G00_ACCEL_FACTOR
  double g0_jerk_factor = 1.0;                  // MD32435 G00_JERK_FACTOR
  double tool_change_time_s = 0;                // M6 duration (not derivable from the program)
  double spindle_ramp_time_s = 0;               // spindle run-up/reversal before a thread or tapping block
  double max_spindle_speed_rpm = 10000;         // MD35100 SPIND_VELO_LIMIT (G96 at the centre)
  int master_spindle = 1;                       // MD20090 SPIND_DEF_MASTER_SPIND (S1=, M1=3 address it)
  double spindle_posctrl_velo_rpm = 500;        // MD35300 SPIND_POSCTRL_VELO (SPOS)
  double spindle_posctrl_accel_rev_s2 = 30;     // MD35210 GEAR_STEP_POSCTRL_ACCEL (SPOS)
  double spindle_speedctrl_accel_rev_s2 = 30;   // MD35200 GEAR_STEP_SPEEDCTRL_ACCEL (run-up, braking)
  // MD35500 SPIND_ON_SPEED_AT_IPO_START: after a programmed speed change the path (not G0) starts
  // only once the spindle is in its set range (1, 2), or at once (0); MD35150 SPIND_DES_VELO_TOL
  // is that range (a share of the set speed).
  int spindle_on_speed_at_ipo_start = 1;
  double spindle_des_velo_tol = 0.1;

  // Interpreter data.
  std::vector<std::string> reset_gcodes;        // MD20150 analogue: G1 G17 G40 G500 G64 SOFT BNAT ...
  std::map<std::string, Eigen::Vector3d> work_offsets;  // "G54" -> offset (mm)
  // "G54" -> RPY rotation of the settable frame, degrees about X, Y, Z (acts inside the offset).
  std::map<std::string, Eigen::Vector3d> work_offset_rotations_deg;
  std::vector<Tool> tools;
  // Swivel data ($TC_CARR23, the kinematic type CYCLE800 works with): "none" (no swivel data:
  // TCOABS/TCOFR warn), "table" (the table turns, the tool stays along the machine axis),
  // "head" (the head turns: after TCOABS/TCOFR the tool length acts along the swivelled axis).
  std::string swivel_kinematics = "none";
  // MD20100 DIAMETER_AX_DEF: the geometry axis with the transverse-axis function (a lathe's X),
  // which DIAMON/DIAM90 and G96 refer to; empty: none (a milling machine).
  std::string diameter_axis;
  bool base_unit_inch = false;                  // MD10240 SCALING_SYSTEM_IS_METRIC = false: the base system is inch
  int tool_change_mode = 1;                     // MD22550 TOOL_CHANGE_MODE: 1 = T prepares, M6 changes; 0 = T changes
  int tool_change_m_code = 6;                   // MD22560 TOOL_CHANGE_M_CODE
  int cutting_edge_default = 1;                 // MD20270 CUTTING_EDGE_DEFAULT (0, n, -1, -2)
  int tool_length_const = 0;  // SD42940 TOOL_LENGTH_CONST: 0 lengths follow the plane, 17/18/19 fixed to that plane's
  int tool_length_type = 0;   // SD42950 TOOL_LENGTH_TYPE: 0 by tool type, 1 every tool as a milling tool, 2 as a turning tool
  bool tool_table_complete = false;             // a T/D missing from the table is an alarm (17190/17180), else a warning
  Eigen::Vector3d start_position = Eigen::Vector3d::Zero();  // in the work coordinate system of the first offset
  double circle_error_const_mm = 0.01;          // MD21000 CIRCLE_ERROR_CONST
  double circle_error_factor = 0.001;           // MD21010 CIRCLE_ERROR_FACTOR
  int cubic_spline_blocks = 8;                  // MD20160 CUBIC_SPLINE_BLOCKS (C-spline window)
  bool cubic_spline_global = false;             // solve the C spline over the whole run instead
  int cutcom_maxnum_check_blocks = 3;           // MD20240
  int cutcom_maxnum_dummy_blocks = 3;           // MD20250
  double cutcom_decel_limit = 0.0;              // SD42528: lowest tool-centre feed share on inside curves (CFC)
  double cutcom_corner_limit_deg = 100.0;       // MD20210: G451 -> transition circle above this direction change
  double cutcom_curve_insert_limit_deg = 10.0;  // MD20230: G450 -> intersection below this direction change
  CompressorData compressor;                    // COMPON/COMPCURV/COMPCAD (JSON object "compressor")
  SmoothingData smoothing;                      // G641/G642/G643/G645 (JSON object "smoothing")

  // Further machine/setting data, inputs and PLC data by their `$` name as programs read them
  // ("$MN_SCALING_SYSTEM_IS_METRIC", "$MA_COMPRESS_POS_TOL[X1]", "$A_IN[3]"). The fields above
  // are answered under their own MD names (see machine_data_values()).
  std::map<std::string, double> machine_data;

  // Index into extra_axes of the axis with this (upper-case) name, or -1.
  int extra_axis_index(std::string_view axis_name) const {
    for (size_t i = 0; i < extra_axes.size(); ++i)
      if (extra_axes[i].name == axis_name) return static_cast<int>(i);
    return -1;
  }

  const Tool* find_tool(const std::string& name, int duplo = 0) const { return find_sister_tool(tools, name, duplo); }
  // The next free duplo number of a name (1 for a new name): sister tools listed without one.
  int next_duplo(const std::string& name) const {
    int d = 0;
    for (const auto& t : tools)
      if (t.name == name) d = std::max(d, t.duplo);
    return d + 1;
  }
  const Tool* find_tool(int number) const {
    for (const auto& t : tools)
      if (t.number == number) return &t;
    return nullptr;
  }
};

// The acceleration of geometry axis `axis` (0..2) in dynamic group `group` before ACC[ax]:
// MD32300 MAX_AX_ACCEL × the group's factor (DYNNORM ... DYNPREC) × the factor of the
// interpolation mode, MD32434 G00_ACCEL_FACTOR for rapids, MD32433 SOFT_ACCEL_FACTOR under SOFT.
// The planner's element limits and the interpreter's tapping limit both start from it.
inline double axis_mode_accel_mm_s2(const MachineProfile& p, size_t axis, size_t group, bool rapid, bool soft) {
  const double mode = rapid ? p.g0_accel_factor : (soft ? p.soft_accel_factor : 1.0);
  return p.axes[axis].max_accel_mm_s2 * p.dynamic_groups[group].max_ax_accel * mode;
}

// A profile that fails validation: the message names the offending key.
class ProfileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Parses and validates a profile (unknown key, wrong unit, negative limit -> ProfileError).
MachineProfile load_profile_json(const std::string& json_text, const std::string& origin);
MachineProfile load_profile_file(const std::string& path);
// A tool table alone in the profile's form: an array of tools, or {"tools": [...]}.
std::vector<Tool> load_tools_json(const std::string& json_text, const std::string& origin);
// The embedded TAJMAC-ZPS MCV 1210 profile.
const MachineProfile& default_profile();
// The profile as JSON in the canonical units (load_profile_json reads it back unchanged).
std::string profile_to_json(const MachineProfile& profile);

}  // namespace drycut::machine
