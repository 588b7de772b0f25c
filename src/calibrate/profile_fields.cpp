#include "calibrate/profile_fields.hpp"

#include <algorithm>

namespace drycut::calibrate {
namespace {

using machine::MachineProfile;

// Per-axis data are set on X, Y and Z alike (the experiment's machine has equal axes; a fit
// cannot tell them apart from path times) and read from X.
double get_jerk(const MachineProfile& p) { return p.axes[0].max_jerk_mm_s3 / 1000.0; }
void set_jerk(MachineProfile& p, double v) {
  for (auto& a : p.axes) a.max_jerk_mm_s3 = v * 1000.0;
}
double get_transition_jerk(const MachineProfile& p) {
  const auto& a = p.axes[0];
  return (a.transition_jerk_mm_s3 > 0 ? a.transition_jerk_mm_s3 : a.max_jerk_mm_s3) / 1000.0;
}
void set_transition_jerk(MachineProfile& p, double v) {
  for (auto& a : p.axes) a.transition_jerk_mm_s3 = v * 1000.0;
}
double get_path_jerk(const MachineProfile& p) {
  if (p.path_jerk_mm_s3 > 0) return p.path_jerk_mm_s3 / 1000.0;
  double smallest = p.axes[0].max_jerk_mm_s3;
  for (const auto& a : p.axes) smallest = std::min(smallest, a.max_jerk_mm_s3);
  return smallest / 1000.0;
}
void set_path_jerk(MachineProfile& p, double v) { p.path_jerk_mm_s3 = v * 1000.0; }
double get_accel(const MachineProfile& p) { return p.axes[0].max_accel_mm_s2 / 1000.0; }
void set_accel(MachineProfile& p, double v) {
  for (auto& a : p.axes) a.max_accel_mm_s2 = v * 1000.0;
}
double get_ovl(const MachineProfile& p) { return p.max_accel_ovl_factor; }
void set_ovl(MachineProfile& p, double v) { p.max_accel_ovl_factor = v; }
double get_ipo(const MachineProfile& p) { return p.ipo_cycle_s * 1000.0; }
void set_ipo(MachineProfile& p, double v) { p.ipo_cycle_s = v / 1000.0; }
double get_short_block(const MachineProfile& p) { return p.short_block_factor; }
void set_short_block(MachineProfile& p, double v) { p.short_block_factor = v; }
double get_soft_accel(const MachineProfile& p) { return p.soft_accel_factor; }
void set_soft_accel(MachineProfile& p, double v) { p.soft_accel_factor = v; }
double get_curv_effect(const MachineProfile& p) { return p.curv_effect_on_path_accel; }
void set_curv_effect(MachineProfile& p, double v) { p.curv_effect_on_path_accel = v; }
double get_tool_change(const MachineProfile& p) { return p.tool_change_time_s; }
void set_tool_change(MachineProfile& p, double v) { p.tool_change_time_s = v; }

}  // namespace

const std::vector<ProfileField>& profile_fields() {
  // Bounds: the ranges docs/calibrate.md gives for each datum (usual values on milling
  // machines, widened so that a fit at a bound says "the data want more than is plausible").
  // The overload factor is fitted as given; its lower bound 1.01 keeps OVL - 1 > 0.
  static const std::vector<ProfileField> fields{
      {"jerk", "MD32431 MAX_AX_JERK", "m/s3", 5, 2000, get_jerk, set_jerk},
      {"transition_jerk", "MD32432 PATH_TRANS_JERK_LIM", "m/s3", 5, 5000, get_transition_jerk, set_transition_jerk},
      {"path_jerk", "MD20600 MAX_PATH_JERK", "m/s3", 1, 2000, get_path_jerk, set_path_jerk},
      {"accel", "MD32300 MAX_AX_ACCEL", "m/s2", 0.2, 30, get_accel, set_accel},
      {"ovl_factor", "MD32310 MAX_ACCEL_OVL_FACTOR", "", 1.01, 10, get_ovl, set_ovl},
      {"ipo_cycle", "MD10050 x MD10070 (IPO cycle)", "ms", 0.5, 20, get_ipo, set_ipo},
      {"short_block_factor", "short-block factor (840Di sl manual 11.3.9)", "", 0.1, 5, get_short_block,
       set_short_block},
      {"soft_accel_factor", "MD32433 SOFT_ACCEL_FACTOR", "", 0.1, 2, get_soft_accel, set_soft_accel},
      {"curv_effect", "MD20602 CURV_EFFECT_ON_PATH_ACCEL", "", 0.05, 0.95, get_curv_effect, set_curv_effect},
      {"tool_change_time", "tool change time (M6)", "s", 0.1, 60, get_tool_change, set_tool_change},
  };
  return fields;
}

const ProfileField* find_profile_field(std::string_view name) {
  for (const auto& f : profile_fields())
    if (f.name == name) return &f;
  return nullptr;
}

std::string profile_field_names() {
  std::string out;
  for (const auto& f : profile_fields()) out += (out.empty() ? "" : ", ") + f.name;
  return out;
}

}  // namespace drycut::calibrate
