#include "report/viewer_library.hpp"

#include <cctype>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string_view>

#ifndef DRYCUT_THREE_JS_DIR
#define DRYCUT_THREE_JS_DIR "/usr/share/javascript/three"
#endif

namespace drycut::report {
namespace {

bool read_file(const std::string& path, std::string& out) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream s;
  s << in.rdbuf();
  out = s.str();
  return static_cast<bool>(in) || in.eof();
}

bool starts_script_end(const std::string& s, size_t i) {  // "</script", any case
  static constexpr std::string_view kEnd = "</script";
  if (s.size() - i < kEnd.size()) return false;
  for (size_t k = 0; k < kEnd.size(); ++k)
    if (std::tolower(static_cast<unsigned char>(s[i + k])) != kEnd[k]) return false;
  return true;
}

}  // namespace

std::string viewer_library_dir() {
  const char* env = std::getenv("DRYCUT_THREE_JS_DIR");
  return env && *env ? std::string(env) : std::string(DRYCUT_THREE_JS_DIR);
}

ViewerLibrary load_viewer_library(const std::string& dir) {
  ViewerLibrary lib;
  for (const char* file : kViewerLibraryFiles) {
    const std::string path = dir + "/" + file;
    std::string text;
    if (!read_file(path, text) || text.empty()) {
      lib.missing = path + " could not be read (Debian package libjs-three)";
      lib.scripts.clear();
      break;
    }
    lib.scripts.push_back(std::move(text));
  }
  return lib;
}

std::string inline_script_text(const std::string& js) {
  std::string out;
  out.reserve(js.size() + 16);
  for (size_t i = 0; i < js.size(); ++i) {
    if (js[i] == '<' && (starts_script_end(js, i) || js.compare(i + 1, 3, "!--") == 0)) {
      out += '<';
      out += '\\';
      continue;
    }
    out += js[i];
  }
  return out;
}

}  // namespace drycut::report
