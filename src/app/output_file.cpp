#include "app/output_file.hpp"

#include <unistd.h>

#include <fstream>
#include <system_error>

#include "machine/alarm.hpp"

namespace drycut::app {

void write_output_file(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw UsageError("cannot write " + path.string());
  out << text;
  out.close();
  if (!out) throw UsageError("error writing " + path.string());
}

void check_output_path(const std::string& output, const std::filesystem::path& program) {
  namespace fs = std::filesystem;
  if (output.empty() || output == "-") return;
  std::error_code ec;
  const bool exists = fs::exists(output, ec);
  if (exists && fs::equivalent(output, program, ec))
    throw UsageError("refusing to write " + output + ": it is the program to be read");
  if (exists && fs::is_directory(output, ec)) throw UsageError("cannot write " + output + ": a directory");
  const fs::path parent = fs::path(output).parent_path();
  const std::string where = exists ? output : (parent.empty() ? std::string(".") : parent.string());
  if (::access(where.c_str(), W_OK) != 0) throw UsageError("cannot write " + output);
}

void check_written(std::FILE* out, const std::string& name) {
  if (out && (std::fflush(out) != 0 || std::ferror(out))) throw UsageError("error writing " + name);
}

}  // namespace drycut::app
