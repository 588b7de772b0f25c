#include "workload/deviation_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "workload/deviation_held_line.hpp"

namespace drycut::workload {
namespace {

Vec2 xy(const Vec3& p) { return {p.x(), p.y()}; }

class StatsAccumulator {
 public:
  void add(double signed_value) {
    const double a = std::abs(signed_value);
    if (s_.samples == 0) s_.min_signed_mm = s_.max_signed_mm = signed_value;
    ++s_.samples;
    s_.max_mm = std::max(s_.max_mm, a);
    sum_ += a;
    sum2_ += a * a;
    s_.min_signed_mm = std::min(s_.min_signed_mm, signed_value);
    s_.max_signed_mm = std::max(s_.max_signed_mm, signed_value);
  }
  DeviationStats result() const {
    DeviationStats r = s_;
    if (r.samples) {
      r.mean_mm = sum_ / static_cast<double>(r.samples);
      r.rms_mm = std::sqrt(sum2_ / static_cast<double>(r.samples));
    }
    return r;
  }

 private:
  DeviationStats s_;
  double sum_ = 0.0, sum2_ = 0.0;
};

DeviationStats programmed_stats(const std::vector<Vec3>& samples, const ReferenceContour& reference) {
  StatsAccumulator acc;
  for (const Vec3& p : samples) acc.add(reference.nearest(xy(p)).distance);
  return acc.result();
}

PolylineIndex xy_index(const std::vector<Vec3>& path) {
  std::vector<Vec2> points;
  points.reserve(path.size());
  for (const Vec3& p : path) points.push_back(xy(p));
  PolylineIndex index;
  index.add_polyline(points, false);
  index.build();
  return index;
}

// Curve samples every ~0.01 mm (every 4th vertex of the dense reference) within the pass's range.
DeviationStats tool_cut_stats(const PolylineIndex& tool, double radius, const ReferenceContour& reference,
                              double u_low, double u_high) {
  StatsAccumulator acc;
  const bool whole = u_high - u_low >= 0.99;
  const auto& v = reference.vertices();
  for (size_t i = 0; i < v.size(); i += 4) {
    const double u = reference.u_of_vertex(i);
    if (!whole && u + std::ceil(u_low - u) > u_high) continue;  // no turn of u lies in [low, high]
    acc.add(tool.nearest(v[i]).distance - radius);
  }
  return acc.result();
}

nlohmann::json optional_json(const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(nullptr); }

nlohmann::json stats_json(const DeviationStats& s, bool signed_values) {
  nlohmann::json j{{"samples", s.samples}, {"max_mm", s.max_mm}, {"mean_mm", s.mean_mm}, {"rms_mm", s.rms_mm}};
  if (signed_values) {
    j["deepest_gouge_mm"] = s.min_signed_mm;
    j["most_material_left_mm"] = s.max_signed_mm;
  }
  return j;
}

nlohmann::json pass_json(const PassDeviation& p) {
  nlohmann::json j{{"name", p.name}, {"full_loop", p.full_loop}, {"mean_z_mm", p.mean_z_mm},
                   {"programmed", stats_json(p.programmed, false)}};
  j["tool_cut"] = p.tool_cut ? stats_json(*p.tool_cut, true) : nlohmann::json(nullptr);
  return j;
}

// The control points on the bottom loop: held-line crossings with its programmed contour and
// with the edge its tool cuts.
void evaluate_control_points(const ContourPass& bottom, double tool_radius_mm,
                             const std::vector<ControlPoint>& control_points, DeviationReport& report) {
  report.control_pass = bottom.name;
  const double range = report.held_line_range_mm;
  const PolylineIndex programmed = xy_index(bottom.programmed);
  const bool with_tool = tool_radius_mm > 0 && !bottom.tool_centre.empty();
  const PolylineIndex tool = with_tool ? xy_index(bottom.tool_centre) : PolylineIndex{};
  std::vector<std::optional<double>> programmed_diffs, tool_diffs;
  for (const ControlPoint& cp : control_points) {
    ControlPointRow row{cp, held_line_polyline_crossing(programmed, cp, range), std::nullopt};
    if (with_tool) row.tool_cut_mm = held_line_cut_crossing(tool, tool_radius_mm, programmed, cp, range);
    programmed_diffs.push_back(row.programmed_mm);
    tool_diffs.push_back(row.tool_cut_mm);
    report.control_points.push_back(row);
  }
  report.programmed_mae = control_point_mae(programmed_diffs);
  if (with_tool) report.tool_cut_mae = control_point_mae(tool_diffs);
}

nlohmann::json mae_json(const ControlPointMae& m) {
  return {{"mae_mm", optional_json(m.mae_mm)}, {"measured", m.measured}, {"without_crossing", m.without_crossing}};
}

// "0.1234 mm over 10 of 11 points, 1 without crossing within 5 mm"
std::string mae_text(const ControlPointMae& m, double range_mm) {
  char b[160];
  if (m.mae_mm) std::snprintf(b, sizeof b, "%.4f mm", *m.mae_mm);
  else std::snprintf(b, sizeof b, "-");
  std::string out = b;
  std::snprintf(b, sizeof b, " over %zu of %zu points, %zu without crossing within %g mm", m.measured, m.points,
                m.without_crossing, range_mm);
  return out + b;
}

}  // namespace

DeviationReport evaluate_deviation(const ContourSplit& split, const ReferenceContour& reference,
                                   const std::vector<ControlPoint>& control_points, double held_line_range_mm) {
  DeviationReport report;
  report.held_line_range_mm = held_line_range_mm;
  report.reference_length_mm = reference.length();
  report.tool_radius_mm = split.tool_radius_mm;
  report.contour_elements = split.contour_elements;
  report.all.name = "all passes";
  std::vector<Vec3> all_programmed, all_tool;
  double z_sum = 0;
  for (const ContourPass& pass : split.passes) {
    PassDeviation row;
    row.name = pass.name;
    row.full_loop = pass.full_loop;
    row.mean_z_mm = pass.mean_z_mm;
    row.programmed = programmed_stats(pass.programmed, reference);
    if (split.tool_radius_mm > 0 && !pass.tool_centre.empty())
      row.tool_cut = tool_cut_stats(xy_index(pass.tool_centre), split.tool_radius_mm, reference, pass.u_low,
                                    pass.u_high);
    report.passes.push_back(std::move(row));
    all_programmed.insert(all_programmed.end(), pass.programmed.begin(), pass.programmed.end());
    all_tool.insert(all_tool.end(), pass.tool_centre.begin(), pass.tool_centre.end());
    z_sum += pass.mean_z_mm * static_cast<double>(pass.programmed.size());
  }
  if (split.passes.empty()) return report;
  report.all.programmed = programmed_stats(all_programmed, reference);
  report.all.mean_z_mm = z_sum / static_cast<double>(all_programmed.size());
  report.all.full_loop = std::any_of(split.passes.begin(), split.passes.end(), [](auto& p) { return p.full_loop; });
  if (split.tool_radius_mm > 0 && !all_tool.empty())
    report.all.tool_cut = tool_cut_stats(xy_index(all_tool), split.tool_radius_mm, reference, 0.0, 1.0);

  evaluate_control_points(split.passes[split.bottom_loop], split.tool_radius_mm, control_points, report);
  return report;
}

nlohmann::json to_json(const DeviationReport& r) {
  nlohmann::json j;
  j["reference_length_mm"] = r.reference_length_mm;
  j["tool_radius_mm"] = r.tool_radius_mm;
  j["contour_elements"] = r.contour_elements;
  j["passes"] = nlohmann::json::array();
  for (const auto& p : r.passes) j["passes"].push_back(pass_json(p));
  j["all_passes"] = pass_json(r.all);
  j["control_point_pass"] = r.control_pass;
  j["control_point_mae_mm"] = optional_json(r.programmed_mae.mae_mm);
  j["tool_cut_control_point_mae_mm"] = optional_json(r.tool_cut_mae ? r.tool_cut_mae->mae_mm : std::nullopt);
  j["held_line_range_mm"] = r.held_line_range_mm;
  j["control_point_summary"] = {{"points", r.control_points.size()},
                                {"programmed", mae_json(r.programmed_mae)},
                                {"tool_cut", r.tool_cut_mae ? mae_json(*r.tool_cut_mae) : nlohmann::json(nullptr)}};
  j["control_points"] = nlohmann::json::array();
  for (const auto& row : r.control_points)
    j["control_points"].push_back({{"x_mm", row.point.nominal.x()},
                                   {"y_mm", row.point.nominal.y()},
                                   {"hold", row.point.hold_x ? "x" : "y"},
                                   {"programmed_difference_mm", optional_json(row.programmed_mm)},
                                   {"programmed_crossing", row.programmed_mm.has_value()},
                                   {"tool_cut_difference_mm", optional_json(row.tool_cut_mm)},
                                   {"tool_cut_crossing", r.tool_cut_mae ? nlohmann::json(row.tool_cut_mm.has_value())
                                                                        : nlohmann::json(nullptr)}});
  return j;
}

std::string format_table(const DeviationReport& r) {
  std::string out;
  char line[256];
  auto cell = [](const std::optional<double>& v, const char* missing = "-") {
    char b[32];
    if (v) std::snprintf(b, sizeof b, "%9.4f", *v);
    else std::snprintf(b, sizeof b, "%9s", missing);
    return std::string(b);
  };
  std::snprintf(line, sizeof line, "reference length %.4f mm, tool radius %.3f mm, %zu contour elements\n",
                r.reference_length_mm, r.tool_radius_mm, r.contour_elements);
  out += line;
  out += "pass          mean Z |  programmed: max      mean       rms | tool cut: max     mean      rms    gouge     left\n";
  auto row = [&](const PassDeviation& p) {
    std::snprintf(line, sizeof line, "%-12s %7.3f | %17.4f %9.4f %9.4f |", p.name.c_str(), p.mean_z_mm,
                  p.programmed.max_mm, p.programmed.mean_mm, p.programmed.rms_mm);
    out += line;
    if (p.tool_cut) {
      out += cell(p.tool_cut->max_mm) + cell(p.tool_cut->mean_mm) + cell(p.tool_cut->rms_mm) +
             cell(p.tool_cut->min_signed_mm) + cell(p.tool_cut->max_signed_mm) + "\n";
    } else {
      out += "   (no compensation)\n";
    }
  };
  for (const auto& p : r.passes) row(p);
  if (!r.passes.empty()) row(r.all);
  if (!r.control_points.empty()) {
    out += "control points on " + r.control_pass + " (difference contour - point along the held line, mm; none: no crossing):\n";
    out += "        x         y hold  programmed  tool cut\n";
    for (const auto& c : r.control_points) {
      std::snprintf(line, sizeof line, "%9.3f %9.3f  %s  ", c.point.nominal.x(), c.point.nominal.y(),
                    c.point.hold_x ? "x" : "y");
      out += line + cell(c.programmed_mm, "none") + "  " + cell(c.tool_cut_mm, r.tool_cut_mae ? "none" : "-") + "\n";
    }
    out += "control-point MAE programmed " + mae_text(r.programmed_mae, r.held_line_range_mm) + "\n";
    if (r.tool_cut_mae) out += "control-point MAE tool cut   " + mae_text(*r.tool_cut_mae, r.held_line_range_mm) + "\n";
  }
  return out;
}

}  // namespace drycut::workload
