#pragma once
// The `axes` object of a machine profile: X, Y, Z (required, linear, mm) and any further
// channel axes by name (rotary ones in degrees). docs/machine-profile.md, docs/axes.md.
#include <nlohmann/json.hpp>

#include "machine/machine_profile.hpp"

namespace drycut::machine {

// Reads every axis; throws ProfileError naming the key path.
void read_axes(const nlohmann::json& node, MachineProfile& profile);
// The axes in the canonical units (read_axes reads it back unchanged).
nlohmann::json axes_to_json(const MachineProfile& profile);

}  // namespace drycut::machine
