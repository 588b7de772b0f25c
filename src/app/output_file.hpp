#pragma once
// Writing a command's output file whole (JSON, HTML, JUnit, baselines, generated programs):
// a path that cannot be opened or written is a usage error (exit code 2) naming the path.
#include <cstdio>
#include <filesystem>
#include <string>

namespace drycut::app {

void write_output_file(const std::filesystem::path& path, const std::string& text);

// An output path a command is about to truncate, checked before any output is opened: refused
// when it names the program to be read (`run --json P.MPF P.MPF` truncated the program before
// reading it) or when it cannot be written (so a bad second path leaves the first file as it
// was). "-" (standard output) and "" (none) pass.
void check_output_path(const std::string& output, const std::filesystem::path& program);

// After writing: flushes the stream and throws UsageError("error writing <name>") when a write
// failed (a full disk, /dev/full); a report cut short must not end as a success.
void check_written(std::FILE* out, const std::string& name);

}  // namespace drycut::app
