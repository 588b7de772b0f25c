#pragma once
// The dynamic G group 59 (DYNNORM, DYNPOS, DYNROUGH, DYNSEMIFIN, DYNFINISH, DYNPREC). On the
// control each of these G codes selects one element of the array-valued dynamic machine data:
// MD32300 MAX_AX_ACCEL, MD32431 MAX_AX_JERK, MD32432 PATH_TRANS_JERK_LIM, MD20600
// MAX_PATH_JERK ("each field element corresponds to a G code of group 59", Siemens, machine
// data lists). Switching the group does not interrupt continuous-path mode (only MD20443
// LOOKAH_FFORM, extended look-ahead, does that; not modelled).
//
// The profile keeps the DYNNORM values where they always were (axes.*, path.*) and, per
// further group, FACTORS on them: a machine builder who sets DYNFINISH to 60 % of the DYNNORM
// acceleration writes `"DYNFINISH": {"max_ax_accel_factor": 0.6}`. A missing group or factor is
// 1, which is what the control does with the factory values (every array element the same).
// docs/machine-profile.md, "Dynamic groups".
#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

#include <nlohmann/json.hpp>

namespace drycut::machine {

// The order of the MD array elements (element 0 = DYNNORM).
enum class DynamicGroup : uint8_t { Norm, Pos, Rough, SemiFinish, Finish, Precision };
inline constexpr size_t kDynamicGroupCount = 6;

struct DynamicGroupFactors {
  double max_ax_accel = 1.0;         // MD32300[group] / MD32300[DYNNORM]
  double max_ax_jerk = 1.0;          // MD32431[group] / MD32431[DYNNORM]
  double path_trans_jerk_lim = 1.0;  // MD32432[group] / MD32432[DYNNORM]
  double max_path_jerk = 1.0;        // MD20600[group] / MD20600[DYNNORM]
};

using DynamicGroupTable = std::array<DynamicGroupFactors, kDynamicGroupCount>;

std::string_view dynamic_group_name(DynamicGroup group);
std::optional<DynamicGroup> dynamic_group_from_name(std::string_view upper_name);

// Reads the profile's "dynamic_groups" object (group name -> factors); ProfileError names the
// offending key. DYNNORM cannot be given: its values are the axes' and the path's own.
void read_dynamic_groups(const nlohmann::json& node, DynamicGroupTable& table);
// The groups whose factors are not all 1, in the form read_dynamic_groups reads.
nlohmann::json dynamic_groups_to_json(const DynamicGroupTable& table);

}  // namespace drycut::machine
