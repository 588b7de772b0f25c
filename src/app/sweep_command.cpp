// `drycut sweep [curve options] --tolerance MM [--methods ...] [--json FILE]`: for each method the
// fewest knots that keep the programmed contour within the tolerance, with the predicted time
// and the program size at that density.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <sstream>

#include <nlohmann/json.hpp>

#include "app/commands.hpp"
#include "app/curve_options.hpp"
#include "app/exit_code.hpp"
#include "app/program_pipeline.hpp"
#include "motion/planner.hpp"
#include "workload/sweep.hpp"

namespace drycut::app {
namespace {

struct SweepCommandOptions {
  CurveOptions curve;
  std::string machine_file;
  double tolerance_mm = 0;
  std::string methods = "linear,aspline,bspline,cspline";
  std::string json_file;
  int overlap = 3;
  int max_knots = 8192;
};

// The 3-D program through compensation and planner with the given profile: time after M0.
std::optional<double> planned_time(const std::filesystem::path& main, const machine::MachineProfile& profile) {
  ProgramOptions options;
  options.program = main.string();
  options.quiet = true;
  motion::PlanObserver none;
  motion::Planner planner(profile, none);
  const PipelineOutcome outcome = run_program_tool_centre(options, profile, planner);
  if (outcome.alarm) return std::nullopt;
  return planner.summary().time_after_m0_s;
}

int run_sweep(const SweepCommandOptions& o) {
  ProgramOptions machine_options;
  machine_options.machine_file = o.machine_file;
  const machine::MachineProfile profile = load_machine(machine_options);
  const workload::CurveSource curve = make_curve(o.curve);
  std::vector<workload::Method> methods;
  std::stringstream list(o.methods);
  for (std::string name; std::getline(list, name, ',');) {
    try {
      methods.push_back(workload::parse_method(name));
    } catch (const std::invalid_argument& e) {
      throw UsageError(e.what());
    }
  }
  workload::SweepOptions options;
  options.tolerance_mm = o.tolerance_mm;
  options.overlap_knots = o.overlap;
  options.max_knots = o.max_knots;
  const workload::TimePredictor predict = [&](const std::filesystem::path& main) { return planned_time(main, profile); };

  nlohmann::json j{{"tolerance_mm", o.tolerance_mm},
                   {"distribution", "equal arc length over the whole curve"},
                   {"judged", "2-D single loop at Z=-6, full loop seam included, overlap knots before/after the seam"},
                   {"overlap_knots", o.overlap},
                   {"methods", nlohmann::json::array()}};
  std::printf("tolerance %.4f mm; knots at equal arc length over the whole curve; 2-D loop with %d overlap knots, seam included\n",
              o.tolerance_mm, o.overlap);
  std::printf("method    knots  spacing mm  max dev mm  time after M0 s  main B   sub B  evaluations\n");
  bool all_found = true;
  for (workload::Method m : methods) {
    const workload::SweepResult r = workload::sweep_method(curve, m, options, profile, predict);
    nlohmann::json row{{"method", workload::method_name(m)}, {"found", r.found}};
    nlohmann::json evaluations = nlohmann::json::array();
    for (const auto& e : r.evaluations)
      evaluations.push_back({{"knots", e.knots},
                             {"max_deviation_mm", std::isfinite(e.max_deviation_mm) ? nlohmann::json(e.max_deviation_mm)
                                                                                    : nlohmann::json(nullptr)}});
    row["evaluations"] = evaluations;
    if (!r.found) {
      all_found = false;
      std::printf("%-8s  not found up to %d knots\n", workload::method_name(m), o.max_knots);
    } else {
      row.update({{"knots", r.knots},
                  {"spacing_mm", r.spacing_mm},
                  {"max_deviation_mm", r.max_deviation_mm},
                  {"time_after_m0_s", r.time_after_m0_s ? nlohmann::json(*r.time_after_m0_s) : nlohmann::json(nullptr)},
                  {"main_bytes", r.main_bytes},
                  {"sub_bytes", r.sub_bytes},
                  {"monotone_neighbourhood", r.monotone}});
      char time[32] = "-";
      if (r.time_after_m0_s) std::snprintf(time, sizeof time, "%.2f", *r.time_after_m0_s);
      std::printf("%-8s %6d %11.4f %11.5f %16s %7zu %7zu %4zu%s\n", workload::method_name(m), r.knots, r.spacing_mm,
                  r.max_deviation_mm, time, r.main_bytes, r.sub_bytes, r.evaluations.size(),
                  r.monotone ? "" : "  (not monotone nearby)");
    }
    j["methods"].push_back(row);
  }
  if (!o.json_file.empty()) {
    std::ofstream out(o.json_file);
    if (!out) throw UsageError("cannot write " + o.json_file);
    out << j.dump(2) << "\n";
  }
  return all_found ? kExitOk : kExitAlarm;
}

}  // namespace

void register_sweep(CLI::App& app) {
  auto o = std::make_shared<SweepCommandOptions>();
  CLI::App* cmd = app.add_subcommand("sweep", "Fewest knots per method that keep the contour within a tolerance");
  add_curve_options(*cmd, o->curve);
  cmd->add_option("--tolerance", o->tolerance_mm, "Largest normal deviation of the programmed contour (mm)")
      ->required()
      ->check(CLI::PositiveNumber);
  cmd->add_option("--methods", o->methods, "Comma-separated: linear,aspline,bspline,cspline")
      ->default_val("linear,aspline,bspline,cspline");
  cmd->add_option("--json", o->json_file, "Write the result as JSON");
  cmd->add_option("--machine", o->machine_file, "Machine profile JSON (default: the embedded one)");
  cmd->add_option("--overlap", o->overlap, "Knots repeated before and after the seam")->default_val(3);
  cmd->add_option("--max-knots", o->max_knots, "Give up above this many knots")->default_val(8192);
  cmd->callback([o] {
    try {
      throw ExitRequest{run_sweep(*o)};
    } catch (const UsageError& e) {
      std::fprintf(stderr, "drycut sweep: %s\n", e.what());
      throw ExitRequest{kExitUsage};
    } catch (const AlarmError& e) {
      std::fprintf(stderr, "%s\n", e.what());
      throw ExitRequest{kExitAlarm};
    }
  });
}

}  // namespace drycut::app
