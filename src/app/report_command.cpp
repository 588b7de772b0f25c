// `drycut report PROGRAM -o report.html [--machine FILE] [--polar EXPR | --parametric ... | --points CSV]`:
// one self-contained HTML page with the run's plots, summary, dips and alarms.
#include "app/report_command.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "app/commands.hpp"
#include "app/exit_code.hpp"
#include "app/interruption.hpp"
#include "app/output_file.hpp"
#include "interp/block_compressor.hpp"
#include "interp/corner_smoothing.hpp"
#include "interp/cutter_compensation.hpp"
#include "motion/planner.hpp"
#include "parser/program_files.hpp"
#include "report/html_element_tap.hpp"
#include "report/html_run_report.hpp"
#include "report/viewer_library.hpp"

namespace drycut::app {

std::optional<ReferenceContour> make_reference(const CurveOptions& options) {
  if (options.polar.empty() && options.parametric.empty() && options.points_csv.empty()) return std::nullopt;
  const workload::CurveSource curve = make_curve(options);
  ReferenceContour r;
  r.contour = std::make_shared<const workload::ReferenceContour>(curve);
  const auto& vertices = r.contour->vertices();
  for (const auto& v : vertices) {
    if (!v.allFinite()) throw UsageError("the reference curve is not finite everywhere");
  }
  // About a thousand points are plenty to draw it.
  const size_t step = std::max<size_t>(1, vertices.size() / 1000);
  for (size_t i = 0; i < vertices.size(); i += step) r.outline.emplace_back(vertices[i].x(), vertices[i].y());
  r.outline.emplace_back(vertices.front().x(), vertices.front().y());
  r.name = !options.polar.empty() ? "r = " + options.polar
           : !options.parametric.empty() ? options.parametric
                                         : options.points_csv;
  return r;
}

ReportRun run_for_report(const ProgramOptions& options, const machine::MachineProfile& profile,
                         const ReferenceContour* reference, bool samples) {
  report::RunPlotOptions plot_options;
  if (reference) {
    auto contour = reference->contour;
    plot_options.distance_to_reference = [contour](double x, double y) {
      return contour->nearest(workload::Vec2(x, y)).distance;
    };
  }
  report::RunPlotCollector collector(plot_options);
  motion::PlannerOptions planner_options;
  planner_options.emit_samples = samples;
  motion::Planner planner(profile, collector, planner_options);
  report::ElementTap tool_centre(planner, [&](const interp::PathElement& e) { collector.on_tool_centre(e); });
  ReportRun run;
  {
    Diagnostics compensation_diagnostics;
    interp::CornerSmoothing smoothing(tool_centre, profile);
    interp::BlockCompressor compressor(smoothing, profile);
    interp::CutterCompensation compensation(compressor, profile, compensation_diagnostics);
    report::ElementTap programmed(compensation, [&](const interp::PathElement& e) { collector.on_programmed(e); });
    run.outcome = run_program(options, profile, programmed);
    for (const auto& a : compensation_diagnostics.items()) run.outcome.diagnostics.report(a);
  }
  run.summary = planner.summary();
  run.plots = collector.plots();
  for (const auto& d : run.summary.dips) run.dip_locations.push_back(collector.locate(d));
  run.machine = profile.name;
  return run;
}

uint64_t program_bytes(const ProgramOptions& options, const std::vector<std::string>& programs_used) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path main(options.program);
  uint64_t bytes = fs::file_size(main, ec);
  if (ec) bytes = 0;
  std::vector<fs::path> dirs{main.has_parent_path() ? main.parent_path() : fs::path(".")};
  for (const auto& d : options.search_path) dirs.emplace_back(d);
  parser::ProgramFiles files(std::move(dirs));
  // programs_used()[0] is the main program itself.
  for (size_t i = 1; i < programs_used.size(); ++i)
    if (auto path = files.find(parser::normalize_program_name(programs_used[i]))) {
      const uint64_t size = fs::file_size(*path, ec);
      if (!ec) bytes += size;
    }
  return bytes;
}

namespace {
struct ReportOptions {
  ProgramOptions program;
  CurveOptions curve;
  std::string output;
  size_t annotated_dips = 10;
};
}  // namespace

void register_report(CLI::App& app) {
  auto o = std::make_shared<ReportOptions>();
  CLI::App* cmd = app.add_subcommand("report", "Write a self-contained HTML report: paths, velocity, dips, alarms");
  add_program_options(*cmd, o->program);
  cmd->add_option("-o,--output", o->output, "HTML file to write")->required();
  cmd->add_option("--dips", o->annotated_dips, "Worst dips marked on the plots")->default_val(10);
  add_curve_options(*cmd, o->curve);
  cmd->callback([o] {
    install_interrupt_handlers();
    try {
      const machine::MachineProfile profile = load_machine(o->program);
      const std::optional<ReferenceContour> reference = make_reference(o->curve);
      // Open the output first: a bad path should fail before a long run, not after it.
      check_output_path(o->output, o->program.program);
      std::ofstream out(o->output, std::ios::binary);
      if (!out) throw UsageError("cannot write " + o->output);
      ReportRun run = run_for_report(o->program, profile, reference ? &*reference : nullptr, true);
      report::RunReportInput input;
      input.program = o->program.program;
      input.machine = run.machine;
      input.summary = run.summary;
      input.diagnostics = run.outcome.diagnostics.items();
      input.ended_in_alarm = run.outcome.alarm;
      input.blocks = run.outcome.blocks;
      input.plots = std::move(run.plots);
      input.dip_locations = run.dip_locations;
      input.annotated_dips = o->annotated_dips;
      input.viewer = std::make_shared<const report::ViewerLibrary>(report::load_viewer_library());
      // Not an error: the page says the same under "3D view" and keeps every other figure.
      if (!input.viewer->available())
        std::fprintf(stderr, "drycut report: no 3D view in the page: %s\n", input.viewer->missing.c_str());
      if (reference) {
        input.reference = reference->outline;
        input.reference_name = reference->name;
      }
      out << report::render_run_report(input);
      out.close();
      if (!out) throw UsageError("cannot write " + o->output);
      throw ExitRequest{report_outcome(run.outcome)};
    } catch (const UsageError& e) {
      std::fprintf(stderr, "drycut report: %s\n", e.what());
      throw ExitRequest{kExitUsage};
    } catch (const AlarmError& e) {
      // A bad --polar expression: an alarm of the expression, not of the program.
      std::fprintf(stderr, "drycut report: %s\n", e.alarm().format().c_str());
      throw ExitRequest{kExitUsage};
    }
  });
}

}  // namespace drycut::app
