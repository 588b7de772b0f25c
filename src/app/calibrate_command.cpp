// `drycut calibrate MEASUREMENTS.json --fit FIELD,... -o PROFILE.json`: fits profile fields to
// measured times and lowest feeds (src/calibrate/calibration.hpp, docs/calibrate.md). Each
// measured program runs through the pipeline once (parse, interpret, tool radius compensation);
// its tool-centre elements are then re-planned in-process for every trial profile.
#include <spdlog/spdlog.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <sstream>
#include <thread>

#include "app/commands.hpp"
#include "app/exit_code.hpp"
#include "app/program_pipeline.hpp"
#include "calibrate/calibration.hpp"

namespace drycut::app {
namespace {

struct CalibrateOptions {
  std::string measurements;
  std::string fit;
  std::string span;
  std::string machine_file;
  std::string output;
  double feed_weight = 0.1;
  unsigned jobs = 0;
  bool no_loo = false;
};

std::vector<const calibrate::ProfileField*> parse_fields(const std::string& list) {
  std::vector<const calibrate::ProfileField*> out;
  std::stringstream in(list);
  std::string name;
  while (std::getline(in, name, ',')) {
    const calibrate::ProfileField* f = calibrate::find_profile_field(name);
    if (!f) throw UsageError("unknown field '" + name + "' (fields: " + calibrate::profile_field_names() + ")");
    for (const auto* g : out)
      if (g == f) throw UsageError("field '" + name + "' given twice");
    out.push_back(f);
  }
  if (out.empty()) throw UsageError("--fit needs at least one field (" + calibrate::profile_field_names() + ")");
  return out;
}

calibrate::RecordedProgram record(const calibrate::MeasuredRun& run, const machine::MachineProfile& profile) {
  calibrate::RecordedProgram program;
  ProgramOptions options;
  options.program = run.program;
  options.quiet = true;
  program.main_file = options.program;
  calibrate::RecordingSink sink(program);
  const PipelineOutcome outcome = run_program_tool_centre(options, profile, sink);
  if (outcome.alarm || outcome.diagnostics.has_alarms()) {
    std::string first;
    for (const auto& a : outcome.diagnostics.items())
      if (a.severity == Severity::Alarm && first.empty()) first = a.format();
    throw UsageError(run.name + " raises an alarm, a stopped run cannot be calibrated: " + first);
  }
  return program;
}

std::string value_text(const calibrate::ProfileField& f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.4g%s%s", v, f.unit.empty() ? "" : " ", f.unit.c_str());
  return buf;
}

void print_report(const calibrate::CalibrationReport& r) {
  std::printf("%-22s %-34s %14s %14s  %s\n", "field", "machine data", "start", "fitted", "");
  for (const auto& f : r.fields)
    std::printf("%-22s %-34s %14s %14s  %s\n", f.field->name.c_str(), f.field->machine_data.c_str(),
                value_text(*f.field, f.start).c_str(), value_text(*f.field, f.fitted).c_str(),
                f.at_bound ? "AT BOUND" : "");
  std::printf("\n%-28s %8s %8s %7s %8s %7s %8s %7s %7s %7s", "program", "measured", "start", "err%", "fitted", "err%",
              "loo", "err%", "feed", "meas");
  for (size_t j = 0; j < r.fields.size(); ++j) std::printf(" %9s%zu", "S", j + 1);
  std::printf("\n");
  for (const auto& run : r.runs) {
    auto err = [&](double t) { return 100.0 * (t - run.measured_s) / run.measured_s; };
    std::printf("%-28s %8.2f %8.2f %+6.1f%% %8.2f %+6.1f%%", run.name.c_str(), run.measured_s, *run.start.time_s,
                err(*run.start.time_s), *run.fitted.time_s, err(*run.fitted.time_s));
    if (run.loo_s)
      std::printf(" %8.2f %+6.1f%%", *run.loo_s, err(*run.loo_s));
    else
      std::printf(" %8s %7s", "-", "");
    std::printf(" %7.0f %7s", run.fitted.min_feed_mm_min.value_or(0.0),
                run.measured_feed ? std::to_string(static_cast<int>(std::lround(*run.measured_feed))).c_str() : "-");
    for (double s : run.sensitivity) std::printf(" %10.3f", s);
    std::printf("\n");
  }
  for (size_t j = 0; j < r.fields.size(); ++j)
    std::printf("%sS%zu = d time / d ln %s (s)", j ? ", " : "\n", j + 1, r.fields[j].field->name.c_str());
  std::printf("\n");
  std::printf("\nmean |time error|: start %.1f %%, fitted %.1f %% (in sample)", r.mape_start, r.mape_fitted);
  if (r.mape_loo) std::printf(", leave-one-out %.1f %%", *r.mape_loo);
  std::printf("\nHuber cost %.6f from start %zu\n", r.huber_cost, r.start_index);
}

int run_calibrate(const CalibrateOptions& o) {
  ProgramOptions machine_options;
  machine_options.machine_file = o.machine_file;
  machine::MachineProfile profile = load_machine(machine_options);
  const auto fields = parse_fields(o.fit);
  calibrate::Measurements measurements;
  try {
    measurements = calibrate::load_measurements(o.measurements);
    if (!o.span.empty()) {
      const report::RunSpan span = report::parse_span(o.span);
      for (auto& run : measurements.runs) run.span = span;
    }
  } catch (const std::exception& e) {
    throw UsageError(e.what());
  }
  std::vector<calibrate::RecordedProgram> programs;
  for (const auto& run : measurements.runs) programs.push_back(record(run, profile));
  calibrate::CalibrationOptions options;
  options.feed_weight = o.feed_weight;
  options.leave_one_out = !o.no_loo;
  options.jobs = o.jobs ? o.jobs : std::max(1u, std::thread::hardware_concurrency());
  calibrate::Calibration calibration(measurements, std::move(programs), profile, fields, options);
  calibrate::CalibrationReport report;
  try {
    report = calibration.run();
  } catch (const calibrate::CalibrationError& e) {
    throw UsageError(e.what());
  }
  spdlog::info("calibrate: {} evaluations", report.evaluations);
  print_report(report);
  std::ofstream out(o.output);
  if (!out) throw UsageError("cannot write " + o.output);
  out << machine::profile_to_json(report.profile);
  return kExitOk;
}

}  // namespace

void register_calibrate(CLI::App& app) {
  auto o = std::make_shared<CalibrateOptions>();
  CLI::App* cmd = app.add_subcommand("calibrate", "Fit machine-profile fields to measured times (docs/calibrate.md)");
  cmd->add_option("MEASUREMENTS", o->measurements, "Measurements JSON (programs relative to it)")->required();
  cmd->add_option("--fit", o->fit, "Fields to fit, comma-separated: " + calibrate::profile_field_names())->required();
  cmd->add_option("--span", o->span, "Span FROM..TO for every run (default: the file's)");
  cmd->add_option("--machine", o->machine_file, "Base machine profile (default: the embedded MCV 1210)");
  cmd->add_option("-o,--output", o->output, "Write the calibrated profile here")->required();
  cmd->add_option("--feed-weight", o->feed_weight, "Weight of ln(lowest feed ratio) against relative time error")
      ->default_val(o->feed_weight)
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--jobs", o->jobs, "Threads planning the runs (default: the cores)");
  cmd->add_flag("--no-loo", o->no_loo, "Skip the leave-one-out refits");
  cmd->callback([o] {
    try {
      throw ExitRequest{run_calibrate(*o)};
    } catch (const UsageError& e) {
      std::fprintf(stderr, "drycut calibrate: %s\n", e.what());
      throw ExitRequest{kExitUsage};
    }
  });
}

}  // namespace drycut::app
