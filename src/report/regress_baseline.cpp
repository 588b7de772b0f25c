#include "report/regress_baseline.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <tuple>

namespace drycut::report {

using nlohmann::json;

namespace {

constexpr const char* kFormat = "drycut-regress-baseline";
constexpr int kVersion = 1;

// `value` to `decimals` places; dividing by the power of ten gives the double nearest the
// decimal, so the file shows 7376.1289, not 7376.128900000001.
double rounded(double value, int decimals) {
  const double scale = std::pow(10.0, decimals);
  return std::isfinite(value) ? std::round(value * scale) / scale : 0.0;
}

json diagnostics_json(const std::vector<DiagnosticKey>& keys) {
  json list = json::array();
  for (const auto& k : keys) list.push_back({{"number", k.number}, {"file", k.file}, {"line", k.line}, {"count", k.count}});
  return list;
}

json figures_json(const ProgramFigures& f) {
  return json{{"time_s", rounded(f.time_s, 4)},
              {"time_after_m0_s", rounded(f.time_after_m0_s, 4)},
              {"min_feed_mm_min", rounded(f.min_feed_mm_min, 3)},
              {"path_length_mm", rounded(f.path_length_mm, 4)},
              {"dips", f.dips},
              {"complete", f.complete},
              {"error", f.error},
              {"alarms", diagnostics_json(f.alarms)},
              {"warnings", diagnostics_json(f.warnings)}};
}

std::vector<DiagnosticKey> read_diagnostics(const json& list) {
  std::vector<DiagnosticKey> keys;
  for (const auto& k : list)
    keys.push_back({k.at("number").get<int>(), k.at("file").get<std::string>(), k.at("line").get<uint32_t>(),
                    k.value("count", size_t{1})});
  std::sort(keys.begin(), keys.end());
  return keys;
}

ProgramFigures read_figures(const std::string& program, const json& j) {
  ProgramFigures f;
  f.program = program;
  f.time_s = j.at("time_s").get<double>();
  f.time_after_m0_s = j.at("time_after_m0_s").get<double>();
  f.min_feed_mm_min = j.at("min_feed_mm_min").get<double>();
  f.path_length_mm = j.at("path_length_mm").get<double>();
  f.dips = j.at("dips").get<size_t>();
  f.complete = j.at("complete").get<bool>();
  f.error = j.value("error", std::string());
  f.alarms = read_diagnostics(j.at("alarms"));
  f.warnings = read_diagnostics(j.at("warnings"));
  return f;
}

}  // namespace

std::string DiagnosticKey::text() const {
  std::string t = std::to_string(number) + " at " + file + ":" + std::to_string(line);
  if (count > 1) t += " x" + std::to_string(count);
  return t;
}

void set_diagnostics(ProgramFigures& figures, const std::vector<Alarm>& diagnostics) {
  std::map<std::tuple<bool, int, std::string, uint32_t>, size_t> counts;
  for (const Alarm& a : diagnostics) {
    const std::string file = std::filesystem::path(a.where.file).filename().string();
    ++counts[{a.severity == Severity::Warning, a.number, file, a.where.line}];
  }
  figures.alarms.clear();
  figures.warnings.clear();
  for (const auto& [key, count] : counts) {
    const auto& [warning, number, file, line] = key;
    (warning ? figures.warnings : figures.alarms).push_back({number, file, line, count});
  }
}

std::string baseline_json(const Baseline& baseline) {
  json programs = json::object();  // nlohmann orders keys: the file is sorted by program
  for (const auto& f : baseline.programs) programs[f.program] = figures_json(f);
  const json j{{"format", kFormat}, {"version", kVersion}, {"machine", baseline.machine}, {"programs", programs}};
  return j.dump(2, ' ', false, json::error_handler_t::replace) + "\n";
}

Baseline parse_baseline(const std::string& text) {
  try {
    const json j = json::parse(text);
    if (j.value("format", std::string()) != kFormat)
      throw UsageError(std::string("not a drycut regress baseline (\"format\" is not \"") + kFormat + "\")");
    if (j.value("version", 0) != kVersion) throw UsageError("baseline version " + j.value("version", json()).dump() + " is not 1");
    Baseline b;
    b.machine = j.value("machine", std::string());
    for (const auto& [program, figures] : j.at("programs").items()) b.programs.push_back(read_figures(program, figures));
    std::sort(b.programs.begin(), b.programs.end(),
              [](const ProgramFigures& x, const ProgramFigures& y) { return x.program < y.program; });
    return b;
  } catch (const json::exception& e) {
    throw UsageError(std::string("baseline: ") + e.what());
  }
}

}  // namespace drycut::report
