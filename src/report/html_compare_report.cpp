#include "report/html_compare_report.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "report/html_escape.hpp"
#include "report/html_page_style.hpp"
#include "report/svg_chart.hpp"

namespace drycut::report {
namespace {

std::string fmt(const char* format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

std::string name_of(const std::string& program) { return std::filesystem::path(program).filename().string(); }

// "stopped by alarm 14040 at A.MPF:9" (the table says once below that the figures are partial).
std::string stopped_where(const RunCompletion& c) {
  return "stopped by alarm " + std::to_string(c.alarm_number) + " at " + name_of(c.file) + ":" + std::to_string(c.line);
}

bool any_incomplete(const std::vector<CompareRow>& rows) {
  for (const auto& r : rows)
    if (!r.completion.complete) return true;
  return false;
}

constexpr const char* kPartialFigures =
    "INCOMPLETE: the run stopped at an alarm; its figures cover only the blocks before it.";

}  // namespace

std::string program_colour(size_t index) {
  // Ten well separated colours (the common categorical palette of plotting tools).
  static constexpr std::array<const char*, 10> kPalette{"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd",
                                                        "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"};
  return kPalette[index % kPalette.size()];
}

std::string compare_table_text(const std::vector<CompareRow>& rows) {
  bool deviation = false;
  size_t width = 7;
  for (const auto& r : rows) {
    deviation = deviation || r.has_deviation;
    width = std::max(width, name_of(r.program).size());
  }
  std::string o;
  char buf[512];
  std::snprintf(buf, sizeof buf, "%-*s %10s %12s %14s %6s %12s %10s", static_cast<int>(width), "program", "time [s]",
                "after M0 [s]", "min F [mm/min]", "dips", "length [mm]", "bytes");
  o += buf;
  if (deviation) o += "  max dev [mm]";
  o += "\n";
  for (const auto& r : rows) {
    std::snprintf(buf, sizeof buf, "%-*s %10.2f %12.2f %14.0f %6zu %12.1f %10llu", static_cast<int>(width),
                  name_of(r.program).c_str(), r.time_s, r.time_after_m0_s, r.min_feed_mm_min, r.dips, r.path_length_mm,
                  static_cast<unsigned long long>(r.program_bytes));
    o += buf;
    if (deviation) o += r.has_deviation ? fmt("  %12.4f", r.max_deviation_mm) : std::string("  ") + std::string(12, '-');
    if (r.alarms) o += "  (" + std::to_string(r.alarms) + " alarm" + (r.alarms > 1 ? "s)" : ")");
    if (!r.completion.complete) o += "  INCOMPLETE, " + stopped_where(r.completion);
    o += "\n";
  }
  if (any_incomplete(rows)) o += std::string(kPartialFigures) + "\n";
  return o;
}

std::string compare_json(const std::vector<CompareRow>& rows) {
  nlohmann::json programs = nlohmann::json::array();
  for (const auto& r : rows)
    programs.push_back({{"program", r.program},
                        {"time_s", r.time_s},
                        {"time_after_m0_s", r.time_after_m0_s},
                        {"min_feed_mm_min", r.min_feed_mm_min},
                        {"dips", r.dips},
                        {"path_length_mm", r.path_length_mm},
                        {"program_bytes", r.program_bytes},
                        {"max_deviation_mm", r.has_deviation ? nlohmann::json(r.max_deviation_mm) : nlohmann::json()},
                        {"alarms", r.alarms},
                        {"complete", r.completion.complete},
                        {"stopped_at", r.completion.complete ? nlohmann::json()
                                                             : nlohmann::json{{"file", r.completion.file},
                                                                              {"line", r.completion.line},
                                                                              {"alarm", r.completion.alarm_number}}}});
  return nlohmann::json{{"programs", programs}}.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

std::string render_compare_report(const std::vector<CompareRow>& rows,
                                  const std::vector<std::pair<double, double>>& reference,
                                  const std::string& reference_name) {
  std::string o = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>drycut compare</title>\n"
                  "<style>" + std::string(kHtmlPageStyle) + "</style>\n</head>\n<body>\n<h1>drycut compare</h1>\n";
  o += "<p class=\"meta\">" + std::to_string(rows.size()) + " programs, same machine and options.</p>\n";
  bool deviation = false;
  for (const auto& r : rows) deviation = deviation || r.has_deviation;
  o += "<table id=\"compare\">\n<tr><th></th><th>program</th><th>time [s]</th><th>time after M0 [s]</th>"
       "<th>lowest feed [mm/min]</th><th>dips</th><th>path length [mm]</th><th>program size [bytes]</th>";
  if (deviation) o += "<th>max deviation [mm]</th>";
  o += "<th>alarms</th></tr>\n";
  for (size_t i = 0; i < rows.size(); ++i) {
    const auto& r = rows[i];
    o += r.completion.complete ? "<tr>" : "<tr class=\"incomplete\">";
    o += "<td><svg width=\"22\" height=\"10\"><line x1=\"0\" y1=\"5\" x2=\"22\" y2=\"5\" stroke=\"" +
         program_colour(i) + "\" stroke-width=\"3\"/></svg></td><td><code>" + html_escape(name_of(r.program)) +
         "</code></td><td class=\"num\">" + fmt("%.2f", r.time_s) + "</td><td class=\"num\">" +
         fmt("%.2f", r.time_after_m0_s) + "</td><td class=\"num\">" + fmt("%.0f", r.min_feed_mm_min) +
         "</td><td class=\"num\">" + std::to_string(r.dips) + "</td><td class=\"num\">" + fmt("%.1f", r.path_length_mm) +
         "</td><td class=\"num\">" + std::to_string(r.program_bytes) + "</td>";
    if (deviation) o += "<td class=\"num\">" + (r.has_deviation ? fmt("%.4f", r.max_deviation_mm) : "&ndash;") + "</td>";
    o += "<td class=\"num\">" + std::to_string(r.alarms) +
         (r.completion.complete ? "" : "<br>incomplete, " + html_escape(stopped_where(r.completion))) + "</td></tr>\n";
  }
  o += "</table>\n";
  if (any_incomplete(rows)) o += "<p id=\"incomplete\" class=\"incomplete\">" + std::string(kPartialFigures) + "</p>\n";
  o += "<h2>Programmed paths, top view</h2>\n";
  SvgChart chart({"compare-paths", "Programmed paths overlaid (XY)", "X [mm]", "Y [mm]", 1100, 820, true, false, 0});
  if (!reference.empty()) {
    std::vector<XY> ref;
    double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
    for (const auto& [x, y] : reference) {
      ref.push_back({x, y});
      x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
    }
    chart.add_line(std::move(ref), "#9a9a9a", 1.0, "reference (" + reference_name + ")", true);
    // Frame the contour; approach and retract moves far from it are clipped.
    const double margin = 0.12 * std::max(x1 - x0, y1 - y0);
    chart.set_view(x0 - margin, x1 + margin, y0 - margin, y1 + margin);
  }
  for (size_t i = 0; i < rows.size(); ++i) {
    std::vector<XY> pts;
    for (const auto& p : rows[i].path) pts.push_back({p.x, p.y});
    chart.add_line(std::move(pts), program_colour(i), 1.3, name_of(rows[i].program));
  }
  o += chart.render();
  o += "<p class=\"note\">Equal scale in X and Y. Paths are decimated for size.</p>\n</body>\n</html>\n";
  return o;
}

}  // namespace drycut::report
