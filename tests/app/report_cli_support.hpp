#pragma once
// Runs the built drycut binary for the report/compare command-line tests.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "cli_support.hpp"

namespace drycut::report_cli {

namespace fs = std::filesystem;

using drycut::testing::CliRun;

// `args` is passed to the shell as written (quote paths yourself); stderr goes to `stderr_file`
// (a file, never a terminal) or is dropped.
inline CliRun run_drycut(const std::string& args, const std::string& stderr_file = "") {
  return drycut::testing::run_shell(drycut::testing::drycut_command(args) + " 2>" +
                                    (stderr_file.empty() ? std::string("/dev/null") : "'" + stderr_file + "'"));
}

inline std::string read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline void write_file(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

inline std::string quoted(const fs::path& p) { return "'" + p.string() + "'"; }

// A fresh temporary folder per test, removed afterwards.
struct TempDir {
  explicit TempDir(const std::string& name)
      : path(fs::temp_directory_path() / (name + "_" + std::to_string(::getpid()))) {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() { fs::remove_all(path); }
  fs::path path;
};

}  // namespace drycut::report_cli
