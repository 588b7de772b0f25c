#include "app/output_file.hpp"

#include <fstream>

#include "machine/alarm.hpp"

namespace drycut::app {

void write_output_file(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw UsageError("cannot write " + path.string());
  out << text;
  out.close();
  if (!out) throw UsageError("error writing " + path.string());
}

}  // namespace drycut::app
