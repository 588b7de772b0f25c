#pragma once
// Running the built drycut binary from the end-to-end tests, and reading the alarm-suite
// expectations (`; expect <alarm> <line> [extra args]` on a program's first line).
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

namespace drycut::testing {

struct CliRun {
  int exit_code = -1;
  std::string out;  // stdout (and stderr where the command line redirects it there)
};

// Runs a shell command line and captures its standard output and exit code.
inline CliRun run_shell(const std::string& command_line) {
  CliRun r;
  FILE* pipe = popen(command_line.c_str(), "r");
  if (!pipe) return r;
  char buf[4096];
  while (size_t n = fread(buf, 1, sizeof buf, pipe)) r.out.append(buf, n);
  const int status = pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

// "'<drycut>' <args>": the binary under test, args in shell syntax (quote paths yourself).
inline std::string drycut_command(const std::string& args) { return std::string("'" DRYCUT_BINARY "' ") + args; }

// `drycut <command> <program> <extra>` run inside the program's folder, stderr merged into out.
inline CliRun run_in_folder(const std::string& command, const std::filesystem::path& program,
                            const std::string& extra_args) {
  return run_shell("cd '" + program.parent_path().string() + "' && " +
                   drycut_command(command + " '" + program.filename().string() + "' " + extra_args) + " 2>&1");
}

struct Expectation {
  int number = 0;
  int line = 0;
  std::string extra_args;
};

inline bool read_expectation(const std::filesystem::path& file, Expectation& e) {
  std::ifstream in(file, std::ios::binary);
  std::string first;
  std::getline(in, first);
  std::istringstream s(first);
  std::string semicolon, word;
  if (!(s >> semicolon >> word >> e.number >> e.line) || semicolon != ";" || word != "expect") return false;
  std::getline(s, e.extra_args);
  return true;
}

// The first alarm in the output: "FILE:LINE:COL: ALARM NUMBER: ..."
inline bool first_alarm(const std::string& output, int& number, int& line) {
  static const std::regex re(R"(:(\d+):(\d+): ALARM (\d+):)");
  std::smatch m;
  if (!std::regex_search(output, m, re)) return false;
  line = std::stoi(m[1]);
  number = std::stoi(m[3]);
  return true;
}

}  // namespace drycut::testing
