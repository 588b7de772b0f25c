#pragma once
// Deviation of a program's contour from the reference curve: per pass and over all passes, for
// the programmed contour (normal distance of each path sample to the curve) and for the surface
// the tool cuts (for each curve sample: distance to the tool-centre path minus the tool radius,
// > 0 material left, < 0 gouge), plus the control-point MAE on the bottom loop (held-line
// crossings, deviation_held_line.hpp; points without a crossing are counted, not averaged).
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "workload/deviation_control_points.hpp"
#include "workload/deviation_passes.hpp"

namespace drycut::workload {

struct DeviationStats {
  size_t samples = 0;
  double max_mm = 0.0;   // largest |deviation|
  double mean_mm = 0.0;  // mean |deviation|
  double rms_mm = 0.0;
  double min_signed_mm = 0.0, max_signed_mm = 0.0;  // tool cut only: deepest gouge, most material left
};

struct PassDeviation {
  std::string name;
  bool full_loop = false;
  double mean_z_mm = 0.0;
  DeviationStats programmed;
  std::optional<DeviationStats> tool_cut;
};

struct ControlPointRow {
  ControlPoint point;
  std::optional<double> programmed_mm, tool_cut_mm;  // nullopt: no crossing (tool cut: or not judged)
};

// How far along the held line a crossing is looked for, on either side of the point.
inline constexpr double kDefaultHeldLineRangeMm = 5.0;

struct DeviationReport {
  double reference_length_mm = 0.0;
  double tool_radius_mm = 0.0;
  size_t contour_elements = 0;
  std::vector<PassDeviation> passes;
  PassDeviation all;                  // every pass together (tool cut: the envelope of all passes)
  std::string control_pass;           // the pass the control points are taken on
  std::vector<ControlPointRow> control_points;
  double held_line_range_mm = kDefaultHeldLineRangeMm;
  ControlPointMae programmed_mae;
  std::optional<ControlPointMae> tool_cut_mae;  // nullopt: no compensation, the cut is not judged
};

DeviationReport evaluate_deviation(const ContourSplit& split, const ReferenceContour& reference,
                                   const std::vector<ControlPoint>& control_points,
                                   double held_line_range_mm = kDefaultHeldLineRangeMm);

nlohmann::json to_json(const DeviationReport& report);
// The printed table (one row per pass and one for all passes, then the control points).
std::string format_table(const DeviationReport& report);

}  // namespace drycut::workload
