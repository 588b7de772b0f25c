#pragma once
// Machine data (as the control writes them, machine_data_file.hpp) → a machine profile.
// docs/machine-data-import.md lists every mapping, its unit conversion and its source.
//
// Algorithm:
//  1. Axes. Machine axis k is addressed as AXk or by its name $MN_AXCONF_MACHAX_NAME_TAB[k-1].
//     Channel 1 (CHANDATA(1)) is the channel drycut models: channel axis c runs on machine axis
//     $MC_AXCONF_MACHAX_USED[c-1] and is named $MC_AXCONF_CHANAX_NAME_TAB[c-1]; geometry axis g
//     (X, Y, Z) is channel axis $MC_AXCONF_GEOAX_ASSIGN_TAB[g-1]. A machine axis with
//     $MA_SPIND_ASSIGN_TO_MACHAX ≠ 0 is a spindle; the master spindle ($MC_SPIND_DEF_MASTER_SPIND)
//     gives the spindle fields. Every other channel axis becomes a further profile axis.
//  2. Values. Each modelled datum is converted from the unit the control stores (mm/min or
//     rev/min, m/s² or rev/s², m/s³ or rev/s³, s, degrees) into the profile; dynamic-response
//     arrays take index 0 (DYNNORM), gear-stage arrays gear stage 1. Per-axis factors the profile
//     holds once (MD32310, MD32433-32435) take the smallest over the geometry axes.
//     Data backups of the same text form add the settable frames ($P_UIFR[n,X,TR/FI/RT] → work
//     offsets G54…), the tool offsets ($TC_DP3..5/$TC_DP6 plus wear $TC_DP12..15, base lengths
//     $TC_DP21..23, type $TC_DP1, cutting edge position $TC_DP2, names $TC_TP2) and the swivel
//     type ($TC_CARR23).
//  3. Missing. A datum the profile needs but the files lack keeps drycut's documented default;
//     each one is listed (which datum, which default).
//  4. The rest. Every numeric datum not mapped goes to `machine_data` under the name a program
//     reads it by (axis index as the machine axis name: $MA_COMPRESS_POS_TOL[X1]).
#include <map>
#include <string>
#include <vector>

#include "machine/machine_data_file.hpp"
#include "machine/machine_profile.hpp"

namespace drycut::machine {

// Where a profile value came from: the datum (with its index) and file:line, or a default.
struct ValueSource {
  std::string datum;   // "$MA_MAX_AX_VELO[AX1]" or "" for a default
  std::string origin;  // "archive.txt:12" or "default"
};

struct MachineDataImport {
  MachineProfile profile;
  std::map<std::string, ValueSource> sources;  // canonical key path ("axes.X.max_velocity_mm_min") -> source
  std::vector<std::string> missing;            // one line per value taken as default
  std::vector<std::string> notes;              // choices made (other channels, differing factors, ...)
  int kept = 0;                                // data kept under machine_data
};

// Throws ProfileError when the imported values fail the profile's validation.
MachineDataImport import_machine_data(const MachineDataText& text, const std::string& profile_name);

// The source map as JSON text ({"key": {"datum": ..., "origin": ...}}, plus "missing" and
// "notes"), written beside an imported profile; and read back (empty map when absent/invalid).
std::string sources_to_json(const MachineDataImport& result);
// `missing`, when given, receives the import's list of values taken as defaults.
std::map<std::string, ValueSource> load_sources_json(const std::string& json_text,
                                                     std::vector<std::string>* missing = nullptr);

}  // namespace drycut::machine
