#include "report/html_run_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <numeric>

#include "report/html_escape.hpp"
#include "report/html_page_style.hpp"
#include "report/html_trace_viewer.hpp"
#include "report/run_completion.hpp"
#include "report/svg_chart.hpp"

namespace drycut::report {
namespace {

constexpr double kMinPerS = 60.0;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string fmt(const char* format, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

std::string row(const std::string& name, const std::string& value) {
  return "<tr><th>" + html_escape(name) + "</th><td class=\"num\">" + value + "</td></tr>\n";
}

std::string where(const std::string& file, uint32_t line) {
  return html_escape(std::filesystem::path(file).filename().string()) + ":" + std::to_string(line);
}

// Highest cutting velocity worth showing: above it only rapids remain (clipped).
double cutting_scale(const RunReportInput& in) {
  double top = in.summary.max_feed_mm_s;
  for (const auto& f : in.plots.feed)
    if (std::isfinite(f.v)) top = std::max(top, f.v);
  return top;
}

std::string summary_table(const RunReportInput& in) {
  const auto& s = in.summary;
  size_t alarms = 0, warnings = 0;
  for (const auto& a : in.diagnostics) (a.severity == Severity::Warning ? warnings : alarms)++;
  std::string o = "<table id=\"summary\">\n";
  o += row("time", fmt("%.2f s", s.time_s));
  o += row("time after M0", fmt("%.2f s", s.time_after_m0_s));
  o += row("path length (tool centre)", fmt("%.1f mm", s.path_length_mm));
  o += row("lowest feed while cutting", fmt("%.0f mm/min", s.min_feed_mm_s * kMinPerS));
  o += row("highest feed while cutting", fmt("%.0f mm/min", s.max_feed_mm_s * kMinPerS));
  o += row("feed dips below 80 % of F", std::to_string(s.dips.size() + s.dips_not_listed));
  o += row("alarms", std::to_string(alarms));
  o += row("warnings", std::to_string(warnings));
  o += row("blocks executed", std::to_string(in.blocks));
  o += row("path elements", std::to_string(s.elements));
  if (in.plots.has_deviation)
    o += row("largest deviation from the reference", fmt("%.4f mm", in.plots.max_deviation_mm));
  o += "</table>\n";
  return o;
}

std::string diagnostics_table(const RunReportInput& in) {
  if (in.diagnostics.empty()) return "<p id=\"alarms\">No alarms, no warnings.</p>\n";
  std::string o = "<table id=\"alarms\">\n<tr><th>kind</th><th>number</th><th>where</th><th>text</th><th>block</th></tr>\n";
  for (const auto& a : in.diagnostics) {
    const bool warning = a.severity == Severity::Warning;
    o += std::string("<tr class=\"") + (warning ? "warning" : "alarm") + "\"><td>" + (warning ? "warning" : "alarm") +
         "</td><td class=\"num\">" + std::to_string(a.number) + "</td><td>" + where(a.where.file, a.where.line) +
         "</td><td>" + html_escape(a.text) + "</td><td class=\"block\">" + html_escape(a.block) + "</td></tr>\n";
  }
  return o + "</table>\n";
}

std::string dip_tooltip(size_t rank, const motion::FeedDip& d) {
  return "dip " + std::to_string(rank) + ": " + fmt("%.0f", d.v_min_mm_s * kMinPerS) + " of " +
         fmt("%.0f mm/min", d.programmed_feed_mm_s * kMinPerS) + ", " + std::string(motion::to_string(d.limit)) +
         ", " + std::filesystem::path(d.min_source.file_name()).filename().string() + ":" +
         std::to_string(d.min_source.line) + " " + d.min_source.text;
}

std::string top_view(const RunReportInput& in, const std::vector<size_t>& worst) {
  SvgChart chart({"top-view", "Top view (XY): tool-centre path coloured by path velocity", "X [mm]", "Y [mm]", 1100,
                  820, true, false, 0});
  if (!in.reference.empty()) {
    std::vector<XY> ref;
    double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
    for (const auto& [x, y] : in.reference) {
      ref.push_back({x, y});
      x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
    }
    chart.add_line(std::move(ref), "#9a9a9a", 1.0, "reference contour (" + in.reference_name + ")", true);
    // The contour is what matters: frame it (with room for the tool radius); approach and
    // retract moves far away are clipped.
    const double margin = 0.12 * std::max(x1 - x0, y1 - y0);
    chart.set_view(x0 - margin, x1 + margin, y0 - margin, y1 + margin);
  }
  std::vector<XY> programmed;
  for (const auto& p : in.plots.programmed_path) programmed.push_back({p.x, p.y});
  chart.add_line(std::move(programmed), "#222", 0.8, "programmed path");
  const double scale = cutting_scale(in);
  std::vector<XY> tool;
  std::vector<double> fraction;
  for (const auto& p : in.plots.tool_path) {
    tool.push_back({p.x, p.y});
    fraction.push_back(scale > 0 ? p.v / scale : 0.0);
  }
  if (!tool.empty()) {
    chart.add_coloured_line(std::move(tool), std::move(fraction), 2.6, "tool centre (colour = velocity)");
    chart.set_colour_bar(0, scale * kMinPerS, "mm/min");
  }
  std::vector<XY> knots;
  for (const auto& k : in.plots.knots) knots.push_back({k.x, k.y});
  std::string knot_legend = "programmed end points (" + std::to_string(in.plots.knot_count) + ")";
  if (in.plots.knot_stride > 1) knot_legend += ", about every " + std::to_string(in.plots.knot_stride) + "th shown";
  chart.add_markers(std::move(knots), "#111", 1.8, knot_legend);
  for (size_t r = 0; r < worst.size() && r < in.annotated_dips; ++r) {
    const size_t i = worst[r];
    if (i < in.dip_locations.size() && in.dip_locations[i].known)
      chart.add_callout({in.dip_locations[i].x, in.dip_locations[i].y}, std::to_string(r + 1),
                        dip_tooltip(r + 1, in.summary.dips[i]));
  }
  return chart.render();
}

// Velocity and programmed F against time (by_time) or tool-centre arc length.
std::string velocity_chart(const RunReportInput& in, const std::vector<size_t>& worst, bool by_time) {
  ChartOptions o{by_time ? "velocity-time" : "velocity-length",
                 by_time ? "Path velocity over time" : "Path velocity along the tool-centre path",
                 by_time ? "time [s]" : "arc length [mm]", "path velocity [mm/min]", 1100, 380, false, true, 0};
  const double scale = cutting_scale(in);
  if (scale > 0) o.y_max = 1.12 * scale * kMinPerS;  // rapids above this are clipped
  SvgChart chart(o);
  std::vector<XY> feed, velocity;
  for (const auto& f : in.plots.feed) feed.push_back({by_time ? f.t : f.s, f.v * kMinPerS});
  for (const auto& p : in.plots.tool_path) velocity.push_back({by_time ? p.t : p.s, p.v * kMinPerS});
  chart.add_line(std::move(velocity), "#2166ac", 1.4, "path velocity");
  chart.add_line(std::move(feed), "#d6604d", 1.6, "F commanded at the tool centre", true);
  for (size_t r = 0; r < worst.size() && r < in.annotated_dips; ++r) {
    const size_t i = worst[r];
    if (i < in.dip_locations.size() && in.dip_locations[i].known)
      chart.add_callout({by_time ? in.dip_locations[i].t : in.dip_locations[i].s, in.summary.dips[i].v_min_mm_s * kMinPerS},
                        std::to_string(r + 1), dip_tooltip(r + 1, in.summary.dips[i]));
  }
  return chart.render();
}

std::string deviation_chart(const RunReportInput& in) {
  SvgChart chart({"deviation", "Deviation of the programmed path from the reference contour (XY)",
                  "programmed arc length [mm]", "deviation [mm]", 1100, 340, false, true, 0});
  std::vector<XY> d;
  for (const auto& p : in.plots.programmed_path) d.push_back({p.s, p.value});
  chart.add_line(std::move(d), "#762a83", 1.4, "distance to " + in.reference_name);
  return chart.render();
}

std::string trace_view(const RunReportInput& in, const std::vector<size_t>& worst) {
  TraceViewerInput v;
  v.trace = &in.plots.trace;
  v.library = in.viewer.get();
  v.scale_mm_s = cutting_scale(in);
  for (size_t r = 0; r < worst.size() && r < in.annotated_dips; ++r) {
    const size_t i = worst[r];
    if (i < in.dip_locations.size() && in.dip_locations[i].known)
      v.dips.push_back({in.dip_locations[i].t, r + 1, dip_tooltip(r + 1, in.summary.dips[i])});
  }
  return trace_viewer_section(v);
}

std::string dip_table(const RunReportInput& in, const std::vector<size_t>& worst) {
  const auto& s = in.summary;
  const size_t total = s.dips.size() + s.dips_not_listed;
  if (total == 0) return "<p id=\"dips\">No feed dips.</p>\n";
  std::string o = "<table id=\"dips\">\n<tr><th>#</th><th>block</th><th>block text</th><th>lowest [mm/min]</th>"
                  "<th>F [mm/min]</th><th>share of F</th><th>cause</th><th>elements</th></tr>\n";
  for (size_t r = 0; r < worst.size() && r < in.dip_table_rows; ++r) {
    const auto& d = s.dips[worst[r]];
    o += "<tr><td class=\"num\">" + std::to_string(r + 1) + (r < in.annotated_dips ? " &#9675;" : "") + "</td><td>" +
         where(d.min_source.file_name(), d.min_source.line) + "</td><td class=\"block\">" +
         html_escape(d.min_source.text) + "</td><td class=\"num\">" + fmt("%.0f", d.v_min_mm_s * kMinPerS) +
         "</td><td class=\"num\">" + fmt("%.0f", d.programmed_feed_mm_s * kMinPerS) + "</td><td class=\"num\">" +
         fmt("%.0f %%", d.programmed_feed_mm_s > 0 ? 100.0 * d.v_min_mm_s / d.programmed_feed_mm_s : 0.0) +
         "</td><td>" + html_escape(std::string(motion::to_string(d.limit))) +
         (d.element_count > 1 && d.main_limit != d.limit ? "; mostly " + std::string(motion::to_string(d.main_limit)) : "") +
         "</td><td class=\"num\">" +
         std::to_string(d.element_count) + "</td></tr>\n";
  }
  o += "</table>\n";
  const size_t shown = std::min(worst.size(), in.dip_table_rows);
  if (total > shown)
    o += "<p class=\"note\">" + std::to_string(total - shown) +
         " more dips not listed (the planner keeps a bounded list; see drycut run --json).</p>\n";
  return o;
}

}  // namespace

std::vector<size_t> dips_worst_first(const motion::PlanSummary& summary) {
  std::vector<size_t> order(summary.dips.size());
  std::iota(order.begin(), order.end(), size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return summary.dips[a].v_min_mm_s < summary.dips[b].v_min_mm_s; });
  return order;
}

std::string render_run_report(const RunReportInput& in) {
  const std::vector<size_t> worst = dips_worst_first(in.summary);
  bool alarms = in.ended_in_alarm;
  for (const auto& a : in.diagnostics) alarms = alarms || a.severity == Severity::Alarm;
  std::string o = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>drycut report: " +
                  html_escape(std::filesystem::path(in.program).filename().string()) + "</title>\n<style>" +
                  std::string(kHtmlPageStyle) + "</style>\n</head>\n<body>\n";
  o += "<h1>drycut report: " + html_escape(std::filesystem::path(in.program).filename().string()) + "</h1>\n";
  o += "<p class=\"meta\">program <code>" + html_escape(in.program) + "</code> on " + html_escape(in.machine) + " &mdash; " +
       (alarms ? "<span class=\"status-alarm\">ended in an alarm</span>" : "<span class=\"status-ok\">ran clean</span>") +
       "</p>\n";
  // A stopped run's figures are partial: the banner stands above every figure of the page.
  const RunCompletion completion = run_completion(in.diagnostics, in.ended_in_alarm);
  if (!completion.complete)
    o += "<p id=\"incomplete\" class=\"incomplete\">Incomplete run: " + html_escape(incomplete_note(completion)) +
         ".</p>\n";
  o += "<h2>Summary</h2>\n" + summary_table(in);
  o += "<h2>Alarms and warnings</h2>\n" + diagnostics_table(in);
  o += trace_view(in, worst);
  o += "<h2>Top view</h2>\n" + top_view(in, worst);
  o += "<p class=\"note\">Equal scale in X and Y; with a reference contour the view frames the contour and clips moves far from it. "
       "Colour: path velocity of the tool centre; faster than the highest cutting F (rapids) shows the top colour. Numbered rings: the worst feed dips (hover for details), listed in the table below.</p>\n";
  o += "<h2>Path velocity</h2>\n" + velocity_chart(in, worst, true) + velocity_chart(in, worst, false);
  o += "<p class=\"note\">Dashed: the F the planner was given for the tool centre (the programmed F, as the compensation stage hands it on; gaps: rapids). Rapid velocities above the "
       "top of the scale are clipped.</p>\n";
  if (in.plots.has_deviation)
    o += "<h2>Deviation along the contour</h2>\n" + deviation_chart(in) +
         "<p class=\"note\">Distance in the XY plane from the programmed path (sampled every 0.05 mm) to the "
         "reference contour. Blocks that do not start and end within 1 mm of the contour (lead-in, lead-out) and rapids are left out.</p>\n";
  o += "<h2>Feed dips</h2>\n" + dip_table(in, worst);
  o += "<p class=\"note\">Plots are decimated for size (" + std::to_string(in.plots.samples) +
       " IPO samples; the lowest and highest value of each stretch are kept, so no dip disappears).</p>\n";
  o += "</body>\n</html>\n";
  return o;
}

}  // namespace drycut::report
