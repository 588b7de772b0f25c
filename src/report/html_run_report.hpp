#pragma once
// The self-contained HTML report of one run: summary, alarms and warnings, top view (tool-centre
// path coloured by velocity, programmed path, knots, dips), velocity over time and over arc
// length with the programmed F, deviation from the reference contour, and the dip table.
// Plots are inline SVG with ids top-view, velocity-time, velocity-length, deviation; the 3D view
// (html_trace_viewer.hpp) is a WebGL canvas with id trace-canvas.
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "machine/alarm.hpp"
#include "motion/plan_result.hpp"
#include "report/html_run_plots.hpp"
#include "report/viewer_library.hpp"

namespace drycut::report {

struct RunReportInput {
  std::string program;  // as given on the command line
  std::string machine;
  motion::PlanSummary summary;
  std::vector<Alarm> diagnostics;  // alarms and warnings in order
  bool ended_in_alarm = false;
  uint64_t blocks = 0;
  RunPlots plots;
  std::vector<DipLocation> dip_locations;  // parallel to summary.dips
  std::vector<std::pair<double, double>> reference;  // reference contour (XY), empty = none
  std::string reference_name;
  size_t annotated_dips = 10;  // dips marked on the plots; all listed ones are in the table
  size_t dip_table_rows = 200;
  // three.js for the 3D view; null or unavailable: the page says why and keeps the top view.
  std::shared_ptr<const ViewerLibrary> viewer;
};

std::string render_run_report(const RunReportInput& input);

// The dips of a summary, worst (lowest velocity) first: indices into summary.dips.
std::vector<size_t> dips_worst_first(const motion::PlanSummary& summary);

}  // namespace drycut::report
