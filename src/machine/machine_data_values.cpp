#include "machine/machine_data_values.hpp"

#include <vector>

namespace drycut::machine {

std::map<std::string, double, std::less<>> machine_data_values(const MachineProfile& p) {
  std::map<std::string, double, std::less<>> md;
  // Units as the control shows them: mm/min, m/s^2, m/s^3, s.
  md["$MN_SCALING_SYSTEM_IS_METRIC"] = p.base_unit_inch ? 0 : 1;  // MD10240
  md["$MN_SYSCLOCK_CYCLE_TIME"] = p.ipo_cycle_s;  // MD10050 (with MD10070 = 1)
  md["$MN_IPO_SYSCLOCK_TIME_RATIO"] = 1;
  md["$MC_SPIND_DEF_MASTER_SPIND"] = p.master_spindle;  // MD20090
  // Data drycut does not model, at their documented defaults (machine data lists of the
  // Function Manuals): builders' macros read them to size loops and tables.
  md["$MN_INT_INCR_PER_MM"] = 1000;   // MD10200 INT_INCR_PER_MM
  md["$MN_INT_INCR_PER_DEG"] = 1000;  // MD10210 INT_INCR_PER_DEG
  md["$MC_MM_NUM_R_PARAM"] = 100;     // MD28050 MM_NUM_R_PARAM
  md["$MC_MAX_PATH_JERK"] = p.path_jerk_mm_s3 / 1000.0;                 // MD20600
  md["$MC_CURV_EFFECT_ON_PATH_ACCEL"] = p.curv_effect_on_path_accel;    // MD20602
  md["$MC_CUBIC_SPLINE_BLOCKS"] = p.cubic_spline_blocks;                // MD20160
  md["$MC_CUTCOM_MAXNUM_CHECK_BLOCKS"] = p.cutcom_maxnum_check_blocks;  // MD20240
  md["$MC_CUTCOM_MAXNUM_DUMMY_BLOCKS"] = p.cutcom_maxnum_dummy_blocks;  // MD20250
  md["$MN_CIRCLE_ERROR_CONST"] = p.circle_error_const_mm;              // MD21000 (channel in newer lists)
  md["$MC_CIRCLE_ERROR_CONST"] = p.circle_error_const_mm;
  md["$MC_CIRCLE_ERROR_FACTOR"] = p.circle_error_factor;               // MD21010
  md["$SC_CUTCOM_DECEL_LIMIT"] = p.cutcom_decel_limit;                 // SD42528
  md["$MC_CUTCOM_CORNER_LIMIT"] = p.cutcom_corner_limit_deg;            // MD20210
  md["$MC_CUTCOM_CURVE_INSERT_LIMIT"] = p.cutcom_curve_insert_limit_deg;  // MD20230
  md["$MC_TOOL_CHANGE_MODE"] = p.tool_change_mode;                     // MD22550
  md["$MC_TOOL_CHANGE_M_CODE"] = p.tool_change_m_code;                 // MD22560
  md["$MC_CUTTING_EDGE_DEFAULT"] = p.cutting_edge_default;             // MD20270
  md["$SC_TOOL_LENGTH_CONST"] = p.tool_length_const;                   // SD42940
  md["$SC_TOOL_LENGTH_TYPE"] = p.tool_length_type;                     // SD42950
  md["$MA_SPIND_VELO_LIMIT[SP1]"] = p.max_spindle_speed_rpm;           // MD35100
  md["$MC_COMPRESS_BLOCK_PATH_LIMIT"] = p.compressor.block_path_limit_mm;  // MD20170
  md["$MC_COMPRESS_VELO_TOL"] = p.compressor.velo_tol_mm_s * 60.0;         // MD20172 (mm/min)
  md["$MC_COMPRESSOR_MODE"] = p.compressor.mode;                           // MD20482
  md["$SC_COMPRESS_CONTUR_TOL"] = p.compressor.contur_tol_mm;              // SD42475
  md["$SC_CRIT_SPLINE_ANGLE"] = p.compressor.crit_spline_angle_deg;        // SD42470
  md["$MC_SMOOTHING_MODE"] = p.smoothing.mode;                             // MD20480
  md["$SC_SMOOTH_CONTUR_TOL"] = p.smoothing.contur_tol_mm;                 // SD42465
  md["$SC_SMOOTH_ORI_TOL"] = p.smoothing.ori_tol_deg;                      // SD42466
  md["$MC_IGNORE_OVL_FACTOR_FOR_ADIS"] = p.smoothing.ignore_ovl_factor ? 1 : 0;  // MD20490
  md["$MC_G0_TOLERANCE_FACTOR"] = p.smoothing.g0_tolerance_factor;         // MD20560
  md["$MC_MM_MAX_AXISPOLY_PER_BLOCK"] = p.smoothing.max_axispoly_per_block;  // MD28520
  // Axis data by machine axis name (X1), channel axis name (X) and machine axis number (AX1:
  // the n-th machine axis; the geometry axes first, then the others, as MD20070 below).
  std::vector<const AxisData*> machine_axes;
  for (const AxisData& a : p.axes) machine_axes.push_back(&a);
  for (const AxisData& a : p.extra_axes) machine_axes.push_back(&a);
  for (size_t n = 0; n < machine_axes.size(); ++n) {
    const AxisData& a = *machine_axes[n];
    // A rotary axis's data are in rev/min, rev/s², rev/s³ (degrees for positions), a linear
    // axis's in mm/min, m/s², m/s³ (machine data lists, MD30300 IS_ROT_AX: the units of the
    // axis-specific data); the profile holds deg/s and mm/s.
    const double velocity_unit = a.rotary ? 60.0 / 360.0 : 60.0;
    const double dynamics_unit = a.rotary ? 1.0 / 360.0 : 1.0 / 1000.0;
    for (const std::string& axis : {a.name + "1", a.name, "AX" + std::to_string(n + 1)}) {
      md["$MA_MAX_AX_VELO[" + axis + "]"] = a.max_velocity_mm_s * velocity_unit;  // MD32000
      md["$MA_POS_AX_VELO[" + axis + "]"] = a.pos_velocity_mm_s * velocity_unit;  // MD32060
      md["$MA_MAX_AX_ACCEL[" + axis + "]"] = a.max_accel_mm_s2 * dynamics_unit;   // MD32300
      md["$MA_MAX_AX_JERK[" + axis + "]"] = a.max_jerk_mm_s3 * dynamics_unit;     // MD32431
      md["$MA_MAX_ACCEL_OVL_FACTOR[" + axis + "]"] = p.max_accel_ovl_factor;      // MD32310
      md["$MA_POS_LIMIT_PLUS[" + axis + "]"] = a.max_mm;                           // MD36110
      md["$MA_POS_LIMIT_MINUS[" + axis + "]"] = a.min_mm;                          // MD36100
      md["$MA_IS_ROT_AX[" + axis + "]"] = a.rotary ? 1 : 0;                        // MD30300
      md["$MA_ROT_IS_MODULO[" + axis + "]"] = a.rotary && a.modulo ? 1 : 0;        // MD30310
      if (a.rotary && a.modulo) md["$MA_MODULO_RANGE[" + axis + "]"] = a.modulo_range;  // MD30330
      md["$MA_COMPRESS_POS_TOL[" + axis + "]"] = a.compress_pos_tol_mm;         // MD33100
      // MD30600 FIX_POINT_POS[k] (G75 FP=k+1) and MD34100 REFP_SET_POS[0]: the profile's
      // fix_points_mm and reference_point_mm (where the profile gives none: the 990007 warning).
      for (size_t k = 0; k < a.fix_points_mm.size(); ++k)
        md["$MA_FIX_POINT_POS[" + std::to_string(k) + "," + axis + "]"] = a.fix_points_mm[k];
      if (a.reference_point_mm) md["$MA_REFP_SET_POS[0," + axis + "]"] = *a.reference_point_mm;
    }
  }
  // MD20050 / MD20070: geometry axis g is channel axis g + 1, channel axis c is machine axis c.
  const size_t channel_axes = p.axes.size() + p.extra_axes.size();
  for (size_t g = 0; g < p.axes.size(); ++g) md["$MC_AXCONF_GEOAX_ASSIGN_TAB[" + std::to_string(g) + "]"] = g + 1.0;
  for (size_t c = 0; c < channel_axes; ++c) md["$MC_AXCONF_MACHAX_USED[" + std::to_string(c) + "]"] = c + 1.0;
  for (const auto& [name, value] : p.machine_data) md[name] = value;
  return md;
}

std::map<std::string, std::string, std::less<>> machine_data_texts(const MachineProfile& p) {
  std::map<std::string, std::string, std::less<>> md;
  size_t c = 0;
  auto channel_axis = [&](const std::string& name) {
    md["$MC_AXCONF_CHANAX_NAME_TAB[" + std::to_string(c) + "]"] = name;
    md["$MN_AXCONF_MACHAX_NAME_TAB[" + std::to_string(c) + "]"] = name + "1";
    ++c;
  };
  for (size_t g = 0; g < p.axes.size(); ++g) {
    md["$MC_AXCONF_GEOAX_NAME_TAB[" + std::to_string(g) + "]"] = p.axes[g].name;
    channel_axis(p.axes[g].name);
  }
  for (const AxisData& a : p.extra_axes) channel_axis(a.name);
  md["$MC_CHAN_NAME"] = "CHAN1";  // MD20000 CHAN_NAME: the default name of channel 1
  if (!p.diameter_axis.empty()) md["$MC_DIAMETER_AX_DEF"] = p.diameter_axis;  // MD20100
  // $TC_CARR23 of swivel data record 1, the kinematic type: T the tool turns (a head), P the part
  // (a table); PGA "Toolholder data". No swivel data: empty (drycut).
  md["$TC_CARR23[1]"] = p.swivel_kinematics == "head" ? "T" : p.swivel_kinematics == "table" ? "P" : "";
  return md;
}

}  // namespace drycut::machine
