#include "machine/dynamic_groups.hpp"

#include <string>

#include "machine/machine_profile.hpp"
#include "machine/profile_object_reader.hpp"

namespace drycut::machine {
namespace {

constexpr std::array<std::string_view, kDynamicGroupCount> kNames{"DYNNORM",    "DYNPOS",    "DYNROUGH",
                                                                  "DYNSEMIFIN", "DYNFINISH", "DYNPREC"};

struct FactorField {
  const char* key;
  double DynamicGroupFactors::*field;
};
constexpr std::array<FactorField, 4> kFields{{
    {"max_ax_accel_factor", &DynamicGroupFactors::max_ax_accel},
    {"max_ax_jerk_factor", &DynamicGroupFactors::max_ax_jerk},
    {"path_trans_jerk_lim_factor", &DynamicGroupFactors::path_trans_jerk_lim},
    {"max_path_jerk_factor", &DynamicGroupFactors::max_path_jerk},
}};

}  // namespace

std::string_view dynamic_group_name(DynamicGroup group) { return kNames[static_cast<size_t>(group)]; }

std::optional<DynamicGroup> dynamic_group_from_name(std::string_view upper_name) {
  for (size_t i = 0; i < kNames.size(); ++i)
    if (kNames[i] == upper_name) return static_cast<DynamicGroup>(i);
  return std::nullopt;
}

void read_dynamic_groups(const nlohmann::json& node, DynamicGroupTable& table) {
  if (!node.is_object()) throw ProfileError("dynamic_groups: must be an object: DYNPOS ... DYNPREC -> factors");
  for (auto it = node.begin(); it != node.end(); ++it) {
    const auto group = dynamic_group_from_name(it.key());
    const std::string path = "dynamic_groups." + it.key();
    if (!group) throw ProfileError(path + ": not a group of G group 59 (DYNPOS, DYNROUGH, DYNSEMIFIN, DYNFINISH, DYNPREC)");
    if (*group == DynamicGroup::Norm)
      throw ProfileError(path + ": DYNNORM's values are the axes' and the path's own; give factors for the other groups");
    ProfileObjectReader r(it.value(), path);
    DynamicGroupFactors& f = table[static_cast<size_t>(*group)];
    for (const auto& [key, field] : kFields)
      if (auto v = r.number(key)) f.*field = require_range(*v, 1e-3, 100.0, r.key_path(key));
    r.reject_unknown_keys();
  }
}

nlohmann::json dynamic_groups_to_json(const DynamicGroupTable& table) {
  nlohmann::json out = nlohmann::json::object();
  for (size_t g = 1; g < table.size(); ++g) {
    nlohmann::json factors = nlohmann::json::object();
    for (const auto& [key, field] : kFields)
      if (table[g].*field != 1.0) factors[key] = table[g].*field;
    if (!factors.empty()) out[std::string(kNames[g])] = factors;
  }
  return out;
}

}  // namespace drycut::machine
