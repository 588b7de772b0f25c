// `drycut deviation PROGRAM [curve options] [--json FILE] [--control-points CSV]`: how far the
// interpolated programmed contour and the surface the tool cuts are from the reference curve.
#include <cstdio>
#include <fstream>
#include <memory>

#include "app/commands.hpp"
#include "app/curve_options.hpp"
#include "app/exit_code.hpp"
#include "app/loader_setup.hpp"
#include "app/program_pipeline.hpp"
#include "workload/deviation_program_run.hpp"
#include "workload/deviation_report.hpp"
#include "workload/programmed_point_deviation.hpp"

namespace drycut::app {
namespace {

struct DeviationOptions {
  ProgramOptions program;
  CurveOptions curve;
  std::string json_file;
  std::string control_points_csv;
  double step_mm = 0.01;
  double capture_mm = 0.5;
  double held_line_range_mm = workload::kDefaultHeldLineRangeMm;
  bool programmed_points = false;
};

// The loader reads the program as `run` does: search path and standard cycles, definition
// files (CYCLE_MACROS.DEF's _FINISH ...), step limit, the machine.
workload::SampleOptions sample_options_for(const DeviationOptions& o, const machine::MachineProfile& profile) {
  workload::SampleOptions s;
  s.loader = make_loader_options(o.program.search_path, o.program.max_steps, o.program.definition_dirs,
                                 o.program.missing_programs_warn, !o.program.no_standard_cycles, profile);
  s.step_mm = o.step_mm;
  return s;
}

void write_json(const std::string& file, const nlohmann::json& j) {
  std::ofstream out(file);
  if (!out) throw UsageError("cannot write " + file);
  out << j.dump(2) << "\n";
}

// --programmed-points: the path the planner gets (compensated, compressed, smoothed) against the
// program's own points, no reference curve. Under G41/G42 that path is the tool centre, so the
// figures include the radius offset.
int run_programmed_points(const DeviationOptions& o) {
  if (!o.curve.polar.empty() || !o.curve.parametric.empty() || !o.curve.points_csv.empty() ||
      !o.control_points_csv.empty())
    throw UsageError("--programmed-points measures the path against the program's own points: no curve or control points");
  const machine::MachineProfile profile = load_machine(o.program);
  const workload::SampleOptions sample_options = sample_options_for(o, profile);
  const workload::SampledProgram sampled = workload::sample_program(o.program.program, profile, sample_options);
  const workload::ProgrammedPointDeviation d =
      workload::programmed_point_deviation(sampled.programmed_points, sampled.tool_centre);
  std::printf("programmed points: %zu in %zu polylines (feed blocks between rapids)\n", d.programmed_points, d.polylines);
  auto where = [](const BlockRef& b) {
    return b.file ? "; max at " + b.file_name() + ":" + std::to_string(b.line) + " " + b.text : std::string();
  };
  std::printf("path -> programmed polyline: max %.4f mm, mean %.4f mm over %zu path samples%s\n",
              d.path_to_polyline.max_mm, d.path_to_polyline.mean_mm, d.path_to_polyline.count,
              where(d.path_to_polyline.max_at).c_str());
  std::printf("programmed points -> path:   max %.4f mm, mean %.4f mm over %zu points%s\n", d.points_to_path.max_mm,
              d.points_to_path.mean_mm, d.points_to_path.count, where(d.points_to_path.max_at).c_str());
  if (!o.json_file.empty()) {
    auto stats = [](const workload::DistanceStats& s) {
      nlohmann::json at = nullptr;
      if (s.max_at.file) at = {{"file", s.max_at.file_name()}, {"line", s.max_at.line}, {"text", s.max_at.text}};
      return nlohmann::json{{"count", s.count}, {"max_mm", s.max_mm}, {"mean_mm", s.mean_mm}, {"max_at", at}};
    };
    nlohmann::json j{{"program", o.program.program},
                     {"sample_step_mm", o.step_mm},
                     {"programmed_points", d.programmed_points},
                     {"polylines", d.polylines},
                     {"path_to_polyline", stats(d.path_to_polyline)},
                     {"points_to_path", stats(d.points_to_path)},
                     {"alarms", nlohmann::json::array()}};
    if (sampled.program_alarm) j["alarms"].push_back(sampled.program_alarm->format());
    write_json(o.json_file, j);
  }
  if (sampled.program_alarm) {
    std::fprintf(stderr, "%s\n", sampled.program_alarm->format().c_str());
    return kExitAlarm;
  }
  return kExitOk;
}

int run_deviation(const DeviationOptions& o) {
  const machine::MachineProfile profile = load_machine(o.program);
  const workload::CurveSource curve = make_curve(o.curve);
  const workload::ReferenceContour reference(curve);
  std::vector<workload::ControlPoint> control_points;
  if (!o.control_points_csv.empty()) control_points = workload::read_control_points(o.control_points_csv);
  else if (o.curve.points_csv.empty()) control_points = workload::thesis_control_points(curve);

  const workload::SampleOptions sample_options = sample_options_for(o, profile);
  const workload::SampledProgram sampled = workload::sample_program(o.program.program, profile, sample_options);
  const workload::ContourSplit split = workload::split_contour(sampled, reference, o.capture_mm);
  const workload::DeviationReport report = workload::evaluate_deviation(split, reference, control_points, o.held_line_range_mm);

  std::fputs(workload::format_table(report).c_str(), stdout);
  if (sampled.compensation_alarm)
    std::printf("tool-centre path stopped by the compensation: %s\n", sampled.compensation_alarm->format().c_str());
  if (!o.json_file.empty()) {
    nlohmann::json j = workload::to_json(report);
    j["program"] = o.program.program;
    j["sample_step_mm"] = o.step_mm;
    j["alarms"] = nlohmann::json::array();
    for (const auto* a : {&sampled.program_alarm, &sampled.compensation_alarm})
      if (*a) j["alarms"].push_back((*a)->format());
    write_json(o.json_file, j);
  }
  if (sampled.program_alarm) {
    std::fprintf(stderr, "%s\n", sampled.program_alarm->format().c_str());
    return kExitAlarm;
  }
  if (split.passes.empty()) {
    std::fprintf(stderr, "drycut deviation: no contour found (no feed move starts and ends within %.3g mm of the curve)\n",
                 o.capture_mm);
    return kExitAlarm;
  }
  return kExitOk;
}

}  // namespace

void register_deviation(CLI::App& app) {
  auto o = std::make_shared<DeviationOptions>();
  CLI::App* cmd = app.add_subcommand(
      "deviation", "Deviation of the programmed and the cut contour from the reference curve (per loop, control points)");
  add_program_options(*cmd, o->program);
  add_curve_options(*cmd, o->curve);
  cmd->add_option("--json", o->json_file, "Write the report as JSON");
  cmd->add_option("--control-points", o->control_points_csv,
                  "CSV x,y[,hold x|y] of control points (default: the thesis's 11 points in the second quadrant)");
  cmd->add_option("--held-line-range", o->held_line_range_mm,
                  "How far (mm) along a control point's held line, on either side, a crossing with the contour is looked for")
      ->default_val(workload::kDefaultHeldLineRangeMm)
      ->check(CLI::PositiveNumber);
  cmd->add_flag("--programmed-points", o->programmed_points,
               "Measure the path against the program's own points (end points of the feed blocks) instead of a curve");
  cmd->add_option("--step", o->step_mm, "Sample spacing along the path in mm")->default_val(0.01)->check(CLI::PositiveNumber);
  cmd->add_option("--capture", o->capture_mm, "A feed move belongs to the contour when both its ends are this close to the curve (mm)")
      ->default_val(0.5)
      ->check(CLI::PositiveNumber);
  cmd->callback([o] {
    try {
      throw ExitRequest{o->programmed_points ? run_programmed_points(*o) : run_deviation(*o)};
    } catch (const UsageError& e) {
      std::fprintf(stderr, "drycut deviation: %s\n", e.what());
      throw ExitRequest{kExitUsage};
    } catch (const AlarmError& e) {
      std::fprintf(stderr, "%s\n", e.what());
      throw ExitRequest{kExitAlarm};
    }
  });
}

}  // namespace drycut::app
