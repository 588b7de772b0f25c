#include "app/program_discovery.hpp"

#include <fnmatch.h>

#include <algorithm>
#include <cctype>
#include <set>
#include <system_error>

#include "machine/alarm.hpp"

namespace drycut::app {

namespace fs = std::filesystem;

namespace {

bool has_glob_characters(const std::string& s) { return s.find_first_of("*?[") != std::string::npos; }

bool is_hidden(const fs::path& p) {
  const std::string name = p.filename().string();
  return name.size() > 1 && name[0] == '.' && name != "..";
}

void add_programs_below(const fs::path& folder, std::set<fs::path>& out) {
  std::error_code ec;
  fs::recursive_directory_iterator it(folder, fs::directory_options::skip_permission_denied, ec), end;
  for (; !ec && it != end; it.increment(ec)) {
    if (it->is_directory(ec) && is_hidden(it->path())) {
      it.disable_recursion_pending();
      continue;
    }
    if (it->is_regular_file(ec) && is_main_program_name(it->path())) out.insert(it->path().lexically_normal());
  }
}

// Expands the pattern components [i, end) below `base`: what exists and matches goes to `hits`.
void expand(const fs::path& base, const std::vector<std::string>& parts, size_t i, std::set<fs::path>& hits) {
  std::error_code ec;
  if (i == parts.size()) {
    if (fs::exists(base, ec)) hits.insert(base.lexically_normal());
    return;
  }
  const std::string& part = parts[i];
  if (!has_glob_characters(part)) {
    expand(base / part, parts, i + 1, hits);
    return;
  }
  const fs::path dir = base.empty() ? fs::path(".") : base;
  if (part == "**") {
    expand(base, parts, i + 1, hits);  // zero folders
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
      if (it->is_directory(ec) && !is_hidden(it->path())) expand(base / it->path().filename(), parts, i, hits);
    return;
  }
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (glob_component_matches(part, name)) expand(base / name, parts, i + 1, hits);
  }
}

std::set<fs::path> glob(const std::string& pattern) {
  std::vector<std::string> parts;
  fs::path base;
  const fs::path p(pattern);
  for (const auto& part : p) {
    if (part == "/" || (parts.empty() && part.has_root_name())) {
      base /= part;
      continue;
    }
    if (!part.empty()) parts.push_back(part.string());
  }
  std::set<fs::path> hits;
  expand(base, parts, 0, hits);
  return hits;
}

}  // namespace

bool is_main_program_name(const fs::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == ".mpf";
}

bool glob_component_matches(const std::string& pattern, const std::string& name) {
  // A leading dot is matched only explicitly (FNM_PERIOD), as the shell does.
  return ::fnmatch(pattern.c_str(), name.c_str(), FNM_PERIOD) == 0;
}

std::vector<fs::path> find_main_programs(const std::vector<std::string>& paths) {
  std::set<fs::path> programs;
  for (const auto& arg : paths) {
    std::error_code ec;
    std::set<fs::path> found;
    if (fs::is_directory(arg, ec)) {
      add_programs_below(arg, found);
    } else if (fs::is_regular_file(arg, ec)) {
      found.insert(fs::path(arg).lexically_normal());
    } else if (has_glob_characters(arg)) {
      for (const auto& hit : glob(arg)) {
        if (fs::is_directory(hit, ec)) add_programs_below(hit, found);
        else if (is_main_program_name(hit)) found.insert(hit);
      }
    } else {
      throw UsageError(arg + ": no such file or folder");
    }
    if (found.empty()) throw UsageError(arg + ": no main program (.MPF) found");
    programs.insert(found.begin(), found.end());
  }
  return {programs.begin(), programs.end()};
}

}  // namespace drycut::app
