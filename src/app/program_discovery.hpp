#pragma once
// Which main programs `drycut regress PATH...` runs. Each PATH is
//   a folder      every main program below it, recursively (hidden folders skipped);
//   a file        that program, whatever its extension;
//   a glob        (quoted, so the shell leaves it) `*`, `?`, `[...]` within one path component
//                 and `**` for any number of folders; the files it matches that are main
//                 programs, and the main programs below the folders it matches.
// A main program is a file with the extension .MPF (any case): on the control, main programs
// live in MPF.DIR and subprograms (.SPF, cycles) are only called; subprograms are then found as
// `run` finds them (the main program's folder, --search-path, the standard cycles).
// The result is sorted and without duplicates; a PATH that names nothing is a UsageError.
#include <filesystem>
#include <string>
#include <vector>

namespace drycut::app {

bool is_main_program_name(const std::filesystem::path& file);

std::vector<std::filesystem::path> find_main_programs(const std::vector<std::string>& paths);

// Whether `name` matches one glob component (`*`, `?`, `[abc]`, `[a-z]`, `[!a]`).
bool glob_component_matches(const std::string& pattern, const std::string& name);

}  // namespace drycut::app
