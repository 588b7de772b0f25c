#pragma once
// A tool table given beside the machine profile (`--tools FILE`): it replaces the profile's
// tool list for one run, so one profile serves all programs while each job brings its tools.
//
// Two forms (docs/machine-profile.md "Tool table file"):
// - JSON: the profile's `tools` array, alone or as {"tools": [...]}.
// - CSV: a header row naming the columns, then one row per cutting edge:
//     number,name,d,length_mm,radius_mm
//     1,FR_4,1,75.5,2
//   `number` and `d` are required; `name` defaults to the number; lengths default to 0; an
//   optional `teeth` column is the number of teeth $TC_DPNT (tooth feed G95 FZ; 0 = unknown). Rows
//   with the same number add edges to one tool. Blank lines and lines starting with # are skipped.
#include <string>
#include <vector>

#include "machine/machine_profile.hpp"

namespace drycut::machine {

// Reads FILE by its extension (.json or .csv); throws ProfileError naming file and line.
std::vector<Tool> load_tool_table_file(const std::string& path);
// The CSV form from text (origin names it in errors).
std::vector<Tool> load_tool_table_csv(const std::string& text, const std::string& origin);

}  // namespace drycut::machine
