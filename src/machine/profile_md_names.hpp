#pragma once
// Which SINUMERIK machine or setting datum each profile key models ("MD32000 MAX_AX_VELO"), for
// `drycut profile show` and the import's source map. Keys are the canonical key paths of
// profile_to_json ("axes.X.max_velocity_mm_min", "path.ipo_cycle_ms").
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace drycut::machine {

// The datum a key models, or "-" when it is a drycut choice with no MD.
std::string md_name_of(std::string_view key_path);

// A profile's JSON as rows (key path, value as compact JSON text) in document order: objects are
// walked, arrays of scalars are one value, arrays of objects are walked as key[i].
std::vector<std::pair<std::string, std::string>> flatten_profile_json(const std::string& json_text);

}  // namespace drycut::machine
