#include "app/standard_cycles.hpp"

#include <string>
#include <system_error>

#include <spdlog/spdlog.h>

// Set by CMake: the installed cycles folder relative to the installed binary's folder
// (CMAKE_INSTALL_DATADIR/drycut/cycles seen from CMAKE_INSTALL_BINDIR).
#ifndef DRYCUT_INSTALLED_CYCLES_RELATIVE
#define DRYCUT_INSTALLED_CYCLES_RELATIVE "../share/drycut/cycles"
#endif

namespace drycut::app {
namespace {

bool is_folder(const std::filesystem::path& p) {
  std::error_code ec;
  return std::filesystem::is_directory(p, ec);
}

// The folder of the running binary (Linux: /proc/self/exe); empty when it cannot be read.
std::filesystem::path binary_folder() {
  std::error_code ec;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) return {};
  return exe.parent_path();
}

}  // namespace

std::optional<std::filesystem::path> standard_cycles_folder() {
  // Looked up once per process (every program run of `regress`, `calibrate` or `experiment` asks):
  // the binary does not move, and a missing folder is reported once, not once per program.
  static const std::optional<std::filesystem::path> folder = [] {
    std::optional<std::filesystem::path> found;
    const auto bin = binary_folder();
    if (!bin.empty()) {
      const auto installed = (bin / DRYCUT_INSTALLED_CYCLES_RELATIVE).lexically_normal();
      if (is_folder(bin / "cycles")) found = bin / "cycles";
      else if (is_folder(installed)) found = installed;
    }
    if (!found) {
      // A binary copied away from its build or install tree: say why CYCLE81 & co. are missing.
      spdlog::warn("drycut's standard cycles folder was not found beside the binary (<bindir>/cycles or "
                   "<bindir>/" DRYCUT_INSTALLED_CYCLES_RELATIVE "); standard cycles called by the program will "
                   "raise 14011 (give their folder with --search-path)");
    }
    return found;
  }();
  return folder;
}

std::vector<std::filesystem::path> search_path_with_cycles(const std::vector<std::string>& user_folders,
                                                           bool use_standard) {
  std::vector<std::filesystem::path> dirs(user_folders.begin(), user_folders.end());
  if (use_standard)
    if (auto cycles = standard_cycles_folder()) dirs.push_back(*cycles);
  return dirs;
}

}  // namespace drycut::app
