#pragma once
// Writing a command's output file whole (JSON, HTML, JUnit, baselines, generated programs):
// a path that cannot be opened or written is a usage error (exit code 2) naming the path.
#include <filesystem>
#include <string>

namespace drycut::app {

void write_output_file(const std::filesystem::path& path, const std::string& text);

}  // namespace drycut::app
