#pragma once
// The `compressor` object of a machine profile: the channel data of the NC block compressor
// COMPON/COMPCURV/COMPCAD (docs/compressor.md, docs/machine-profile.md). The per-axis tolerance
// MD33100 lives in the axis objects (`compress_pos_tol_mm`).
#include <nlohmann/json.hpp>

#include "machine/machine_profile.hpp"

namespace drycut::machine {

// Reads the object into profile.compressor; throws ProfileError naming the key path.
void read_compressor(const nlohmann::json& node, MachineProfile& profile);
// The object in canonical units (read_compressor reads it back unchanged).
nlohmann::json compressor_to_json(const MachineProfile& profile);

// The `smoothing` object: corner smoothing G641/G642/G643/G645 (docs/smoothing.md).
void read_smoothing(const nlohmann::json& node, MachineProfile& profile);
nlohmann::json smoothing_to_json(const MachineProfile& profile);

}  // namespace drycut::machine
