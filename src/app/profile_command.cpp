// `drycut profile import FILE... -o PROFILE.json`: machine data as the control writes them →
// a machine profile, with a source map beside it (PROFILE.sources.json).
// `drycut profile show [PROFILE]`: a profile as a table: key, value, the MD it models, and where
// the value came from (file:line of the machine data, the profile file, or drycut's default).
#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <sstream>

#include "app/commands.hpp"
#include "app/exit_code.hpp"
#include "default_profile_json.hpp"
#include "machine/machine_data_import.hpp"
#include "machine/machine_profile.hpp"
#include "machine/profile_md_names.hpp"
#include "machine/profile_units.hpp"

namespace drycut::app {
namespace {

struct ImportOptions {
  std::vector<std::string> files;
  std::string output;
  std::string name;
};

std::filesystem::path sources_path(const std::filesystem::path& profile) {
  std::filesystem::path p = profile;
  return p.replace_extension(".sources.json");
}

bool write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text << '\n';
  return static_cast<bool>(out);
}

std::optional<std::string> read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

int run_import(const ImportOptions& o) {
  machine::MachineDataText text;
  machine::MachineDataImport result;
  try {
    for (const auto& f : o.files) machine::read_machine_data_file(f, text);
    result =
        machine::import_machine_data(text, o.name.empty() ? std::filesystem::path(o.output).stem().string() : o.name);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "drycut: %s\n", e.what());
    return kExitUsage;
  }
  if (!write_text(o.output, machine::profile_to_json(result.profile)) ||
      !write_text(sources_path(o.output), machine::sources_to_json(result))) {
    std::fprintf(stderr, "drycut: cannot write %s\n", o.output.c_str());
    return kExitUsage;
  }
  int from_files = 0;
  for (const auto& [key, s] : result.sources) from_files += s.origin != "default";
  std::printf("%s: %zu machine data read, %d profile values from them, %d kept under machine_data\n", o.output.c_str(),
              text.data.size(), from_files, result.kept);
  std::printf("source map: %s\n", sources_path(o.output).string().c_str());
  if (!result.missing.empty()) std::printf("missing (drycut's default taken):\n");
  for (const auto& m : result.missing) std::printf("  %s\n", m.c_str());
  if (!result.notes.empty()) std::printf("notes:\n");
  for (const auto& n : result.notes) std::printf("  %s\n", n.c_str());
  return kExitOk;
}

// The quantity of a canonical key without its unit ("max_velocity_mm_min" -> "max_velocity").
std::string quantity_stem(const std::string& last) {
  for (const char* suffix :
       {"_mm_min", "_deg_min", "_m_s2", "_deg_s2", "_m_s3", "_deg_s3", "_mm", "_deg", "_ms", "_s"}) {
    const std::string s = suffix;
    if (last.size() > s.size() && last.compare(last.size() - s.size(), s.size(), s) == 0)
      return last.substr(0, last.size() - s.size());
  }
  return last;
}

bool is_unit_suffix(const std::string& suffix) {
  using machine::Dimension;
  for (Dimension d :
       {Dimension::Length, Dimension::Velocity, Dimension::Acceleration, Dimension::Jerk, Dimension::Time,
        Dimension::Angle, Dimension::AngularVelocity, Dimension::AngularAcceleration, Dimension::AngularJerk})
    for (const auto& u : machine::units_of(d))
      if (u.suffix == suffix) return true;
  return false;
}

// Whether the profile text itself gives the key, in any accepted unit (max_velocity_m_min for
// max_velocity_mm_min), or as a whole object/array the key lies in.
bool given_in(const std::set<std::string>& raw_keys, const std::string& key) {
  if (raw_keys.count(key)) return true;
  const size_t dot = key.rfind('.');
  const std::string parent = key.substr(0, dot + 1);
  const std::string last = key.substr(dot + 1);
  const std::string stem = quantity_stem(last);
  if (stem == last) return false;
  for (const auto& r : raw_keys)
    if (r.size() > parent.size() + stem.size() + 1 && r.compare(0, parent.size(), parent) == 0 &&
        r.compare(parent.size(), stem.size() + 1, stem + "_") == 0 &&
        is_unit_suffix(r.substr(parent.size() + stem.size() + 1)))
      return true;
  return false;
}

int run_show(const std::string& path) {
  machine::MachineProfile profile;
  std::string raw, origin;
  try {
    if (path.empty()) {
      profile = machine::default_profile();
      raw = kDefaultProfileJson;
      origin = "embedded mcv1210.json";
    } else {
      profile = machine::load_profile_file(path);
      raw = read_text(path).value_or("{}");
      origin = std::filesystem::path(path).filename().string();
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "drycut: %s\n", e.what());
    return kExitUsage;
  }
  std::map<std::string, machine::ValueSource> sources;
  std::vector<std::string> missing;
  if (!path.empty())
    if (auto text = read_text(sources_path(path))) sources = machine::load_sources_json(*text, &missing);
  std::set<std::string> raw_keys;
  for (const auto& [k, v] : machine::flatten_profile_json(raw)) raw_keys.insert(k);
  std::printf("%s\n", profile.name.c_str());
  std::printf("%-44s %-22s %-44s %s\n", "key", "value", "machine datum", "source");
  for (const auto& [key, value] : machine::flatten_profile_json(machine::profile_to_json(profile))) {
    if (key == "name") continue;
    std::string source = given_in(raw_keys, key) ? origin : "default";
    if (auto it = sources.find(key); it != sources.end()) source = it->second.origin;
    const std::string shown = value.size() > 22 ? value.substr(0, 19) + "..." : value;
    std::printf("%-44s %-22s %-44s %s\n", key.c_str(), shown.c_str(), machine::md_name_of(key).c_str(), source.c_str());
  }
  if (!missing.empty()) std::printf("missing from the machine data at import (default taken):\n");
  for (const auto& m : missing) std::printf("  %s\n", m.c_str());
  return kExitOk;
}

}  // namespace

void register_profile(CLI::App& app) {
  CLI::App* cmd = app.add_subcommand("profile", "Machine profiles: import machine data, show a profile");
  cmd->require_subcommand(1);
  auto io = std::make_shared<ImportOptions>();
  CLI::App* imp = cmd->add_subcommand("import", "Machine data files (MD text, archive) -> a machine profile");
  imp->add_option("files", io->files, "Machine data files ($MN_/$MC_/$MA_ lines, CHANDATA sections)")->required();
  imp->add_option("-o,--output", io->output,
                  "The profile to write (PROFILE.json; the source map goes to PROFILE.sources.json)")
      ->required();
  imp->add_option("--name", io->name, "The profile's name (default: the output file's name)");
  imp->callback([io] { throw ExitRequest{run_import(*io)}; });
  auto show_path = std::make_shared<std::string>();
  CLI::App* show = cmd->add_subcommand("show", "Print a profile as a table with each value's machine datum and source");
  show->add_option("profile", *show_path, "The profile (default: the embedded MCV 1210)");
  show->callback([show_path] { throw ExitRequest{run_show(*show_path)}; });
}

}  // namespace drycut::app
