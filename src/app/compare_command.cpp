// `drycut compare A.MPF B.MPF ... [--json FILE] [--html FILE] [--polar EXPR ...]`: runs every
// program on the same machine and sets their figures side by side.
#include <cstdio>
#include <fstream>

#include "app/output_file.hpp"
#include "app/commands.hpp"
#include "app/exit_code.hpp"
#include "app/report_command.hpp"
#include "report/html_compare_report.hpp"

namespace drycut::app {
namespace {

struct CompareOptions {
  ProgramOptions program;  // everything but the program name is shared
  std::vector<std::string> programs;
  CurveOptions curve;
  std::string json_file;
  std::string html_file;
};

}  // namespace

void register_compare(CLI::App& app) {
  auto o = std::make_shared<CompareOptions>();
  CLI::App* cmd = app.add_subcommand("compare", "Run several programs and compare time, feed, dips, size, deviation");
  cmd->add_option("PROGRAMS", o->programs, "Main programs (.MPF)")->required();
  // The options of a single run (--search-path, --definitions, --machine, --tools, ...), as run
  // and regress take them: until 2026-11-30 compare listed its own and lacked --definitions and
  // --missing-programs.
  add_run_options(*cmd, o->program);
  cmd->add_option("--json", o->json_file, "Write the comparison as JSON");
  cmd->add_option("--html", o->html_file, "Write an HTML page with the table and the paths overlaid");
  add_curve_options(*cmd, o->curve);
  cmd->callback([o] {
    try {
      const machine::MachineProfile profile = load_machine(o->program);
      const std::optional<ReferenceContour> reference = make_reference(o->curve);
      std::vector<report::CompareRow> rows;
      bool any_alarm = false;
      for (const auto& program : o->programs) {
        ProgramOptions options = o->program;
        options.program = program;
        ReportRun run = run_for_report(options, profile, reference ? &*reference : nullptr, false);
        report::CompareRow row;
        row.program = program;
        row.time_s = run.summary.time_s;
        row.time_after_m0_s = run.summary.time_after_m0_s;
        row.min_feed_mm_min = run.summary.min_feed_mm_s * 60.0;
        row.dips = run.summary.dips.size() + run.summary.dips_not_listed;
        row.path_length_mm = run.summary.path_length_mm;
        row.program_bytes = program_bytes(options, run.outcome.programs_used);
        row.has_deviation = run.plots.has_deviation;
        row.max_deviation_mm = run.plots.max_deviation_mm;
        for (const auto& a : run.outcome.diagnostics.items()) {
          if (a.severity == Severity::Alarm) ++row.alarms;
          std::fprintf(stderr, "%s\n", a.format().c_str());
        }
        row.completion = report::run_completion(run.outcome.diagnostics.items(), run.outcome.alarm);
        any_alarm = any_alarm || run.outcome.alarm || row.alarms > 0;
        row.path = std::move(run.plots.programmed_path);
        rows.push_back(std::move(row));
      }
      std::fputs(report::compare_table_text(rows).c_str(), stdout);
      if (!o->json_file.empty()) write_output_file(o->json_file, report::compare_json(rows));
      if (!o->html_file.empty())
        write_output_file(o->html_file, report::render_compare_report(rows, reference ? reference->outline
                                                                               : std::vector<std::pair<double, double>>{},
                                                               reference ? reference->name : ""));
      throw ExitRequest{any_alarm ? kExitAlarm : kExitOk};
    } catch (const UsageError& e) {
      std::fprintf(stderr, "drycut compare: %s\n", e.what());
      throw ExitRequest{kExitUsage};
    } catch (const AlarmError& e) {
      std::fprintf(stderr, "drycut compare: %s\n", e.alarm().format().c_str());
      throw ExitRequest{kExitUsage};
    }
  });
}

}  // namespace drycut::app
