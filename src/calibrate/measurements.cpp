#include "calibrate/measurements.hpp"

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

namespace drycut::calibrate {
namespace {

report::RunSpan span_of(const nlohmann::json& j, const std::string& where) {
  if (!j.is_string()) throw MeasurementsError(where + ": must be a string FROM..TO");
  try {
    return report::parse_span(j.get<std::string>());
  } catch (const std::invalid_argument& e) {
    throw MeasurementsError(where + ": " + e.what());
  }
}

double positive(const nlohmann::json& run, const char* key, const std::string& where) {
  const auto& v = run.at(key);
  if (!v.is_number() || v.get<double>() <= 0) throw MeasurementsError(where + "." + key + ": must be a number > 0");
  return v.get<double>();
}

}  // namespace

Measurements load_measurements(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw MeasurementsError(path + ": cannot read");
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw MeasurementsError(path + ": not JSON: " + e.what());
  }
  if (!doc.is_object() || !doc.contains("runs") || !doc["runs"].is_array() || doc["runs"].empty())
    throw MeasurementsError(path + ": needs a non-empty array \"runs\"");
  report::RunSpan default_span;
  if (doc.contains("span")) default_span = span_of(doc["span"], path + ": span");
  Measurements out;
  if (doc.contains("min_feed_window")) {
    const auto& w = doc["min_feed_window"];
    if (!w.is_object()) throw MeasurementsError(path + ": min_feed_window: must be an object");
    out.feed_window = FeedWindow{w.value("file_suffix", ""), w.value("between", "")};
  }
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  for (size_t i = 0; i < doc["runs"].size(); ++i) {
    const auto& run = doc["runs"][i];
    const std::string where = path + ": runs[" + std::to_string(i) + "]";
    if (!run.is_object() || !run.contains("program") || !run["program"].is_string())
      throw MeasurementsError(where + ": needs \"program\" (a file name relative to the measurements file)");
    if (!run.contains("time")) throw MeasurementsError(where + ": needs \"time\" (s)");
    MeasuredRun m;
    m.name = run["program"].get<std::string>();
    m.program = (folder / m.name).lexically_normal().string();
    if (!std::filesystem::exists(m.program)) throw MeasurementsError(where + ": program not found: " + m.program);
    m.time_s = positive(run, "time", where);
    if (run.contains("min_feed")) m.min_feed_mm_min = positive(run, "min_feed", where);
    m.span = run.contains("span") ? span_of(run["span"], where + ".span") : default_span;
    out.runs.push_back(std::move(m));
  }
  return out;
}

}  // namespace drycut::calibrate
