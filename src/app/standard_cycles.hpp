#pragma once
// Where drycut's own standard cycles are: NC subprograms (CYCLE81.SPF, CYCLE800.SPF, ...) from
// programs/cycles, installed beside the binary. They are searched after the user's folders, so a
// machine's own cycle (e.g. from a controller archive) with the same name is used instead.
//
// Lookup order: <bindir>/cycles (the build tree, where CMake copies them on every build), then
// the installed folder <bindir>/<relative path> (DRYCUT_INSTALLED_CYCLES_RELATIVE, set by CMake
// from the install directories: ../share/drycut/cycles by default). The first folder that exists
// wins. No absolute path is compiled in, so an installed or packaged drycut never reads the build
// machine's source tree.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace drycut::app {

// Looked up once per process; when no folder is found, one warning says so (a binary copied
// away from its tree would otherwise fail every cycle call with an unexplained 14011).
std::optional<std::filesystem::path> standard_cycles_folder();

// The user's folders followed by the standard cycles folder (when found and `use_standard`).
std::vector<std::filesystem::path> search_path_with_cycles(const std::vector<std::string>& user_folders,
                                                           bool use_standard);

}  // namespace drycut::app
