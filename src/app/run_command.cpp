// `drycut run PROGRAM [--machine FILE] [--json FILE|-] [--ndjson FILE|-] [--trace FILE.csv]`:
// plans the program on the machine and reports time, feed and dips. With the JSON on standard
// output (`-`) the text summary goes to standard error, so the stream stays pure JSON.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>

#include "app/commands.hpp"
#include "app/exit_code.hpp"
#include "app/interruption.hpp"
#include "app/output_file.hpp"
#include "app/program_pipeline.hpp"
#include "motion/planner.hpp"
#include "report/html_element_tap.hpp"
#include "report/run_completion.hpp"
#include "report/run_events.hpp"
#include "report/run_report_writer.hpp"
#include "report/trace_csv_writer.hpp"

namespace drycut::app {
namespace {

struct RunOptions {
  ProgramOptions program;
  std::string json_file;
  std::string ndjson_file;
  std::string trace_file;
  size_t dips_shown = 10;
  std::string span;  // FROM..TO, empty: none
};

using FilePtr = std::unique_ptr<std::FILE, int (*)(std::FILE*)>;

int close_unless_stdout(std::FILE* f) { return f == stdout ? std::fflush(f) : std::fclose(f); }

FilePtr open_output(const std::string& path) {
  if (path == "-") return FilePtr(stdout, &close_unless_stdout);
  FilePtr f(std::fopen(path.c_str(), "w"), &std::fclose);
  if (!f) throw UsageError("cannot write " + path);
  return f;
}

void print_span(std::FILE* out, const report::RunEventRecorder& events, const report::RunSpan& span) {
  const auto s = events.span_s(span);
  if (s) {
    std::fprintf(out, "  span %-20s %6.2f s\n", report::span_name(span).c_str(), *s);
    return;
  }
  std::string missing;
  for (auto e : {span.from, span.to})
    if (!events.time_of(e)) missing = std::string(report::event_name(e));
  std::fprintf(out, "  span %-20s      - (the run has no %s)\n", report::span_name(span).c_str(), missing.c_str());
}

void print_summary(std::FILE* out, const RunOptions& o, const machine::MachineProfile& profile,
                   const motion::PlanSummary& s, const report::RunCompletion& completion,
                   const std::vector<std::string>& untimed) {
  std::fprintf(out, "%s on %s\n", std::filesystem::path(o.program.program).filename().string().c_str(), profile.name.c_str());
  // A stopped run's figures are partial: say so before them, not after.
  if (!completion.complete) std::fprintf(out, "  INCOMPLETE: %s\n", report::incomplete_note(completion).c_str());
  // So is the time of a run with cycles drycut does not simulate.
  if (!untimed.empty()) {
    std::string names;
    for (const auto& n : untimed) names += (names.empty() ? "" : ", ") + n;
    std::fprintf(out, "  NOT TIMED: %s (warning 62900): the time below leaves them out\n", names.c_str());
  }
  std::fprintf(out, "  time               %9.2f s\n", s.time_s);
  std::fprintf(out, "  time after M0      %9.2f s\n", s.time_after_m0_s);
  std::fprintf(out, "  path length        %9.1f mm\n", s.path_length_mm);
  std::fprintf(out, "  feed while cutting %9.0f .. %.0f mm/min\n", s.min_feed_mm_s * 60, s.max_feed_mm_s * 60);
  const size_t total_dips = s.dips.size() + s.dips_not_listed;
  std::fprintf(out, "  feed dips below 80 %% of F: %zu\n", total_dips);
  std::vector<const motion::FeedDip*> dips;
  for (const auto& d : s.dips) dips.push_back(&d);
  std::sort(dips.begin(), dips.end(), [](auto* a, auto* b) { return a->v_min_mm_s < b->v_min_mm_s; });
  for (size_t i = 0; i < std::min(dips.size(), o.dips_shown); ++i) {
    const auto& d = *dips[i];
    std::string block = d.min_source.text.size() > 40 ? d.min_source.text.substr(0, 37) + "..." : d.min_source.text;
    std::fprintf(out, "    %s:%u  %6.0f of %.0f mm/min  %-11s %s\n",
                std::filesystem::path(d.min_source.file_name()).filename().string().c_str(), d.min_source.line,
                d.v_min_mm_s * 60, d.programmed_feed_mm_s * 60, std::string(motion::to_string(d.limit)).c_str(),
                block.c_str());
    // A stretch bound elsewhere by another limit than at its lowest point: say which, or a pass
    // held down by the short-block rule reads as one corner.
    if (d.element_count > 1 && d.main_limit != d.limit)
      std::fprintf(out, "      a stretch of %zu blocks, %.1f mm, mostly %s\n", d.element_count, d.length_mm,
                   std::string(motion::to_string(d.main_limit)).c_str());
  }
  if (dips.size() > o.dips_shown) std::fprintf(out, "    ... %zu more (see --json)\n", total_dips - o.dips_shown);
}

// What the NC block compressor made of the run (docs/compressor.md): one summary line.
struct CompressionTally {
  uint64_t elements = 0, blocks = 0;
  double max_deviation_mm = 0;
  // Corner smoothing G641..G645 (docs/smoothing.md): rounded corners and their largest deviation.
  uint64_t corners = 0;
  double max_corner_deviation_mm = 0;
  void add(const interp::PathElement& e) {
    if (e.smoothing_deviation_mm >= 0) {
      ++corners;
      max_corner_deviation_mm = std::max(max_corner_deviation_mm, e.smoothing_deviation_mm);
    }
    if (e.compressed_blocks == 0) return;
    ++elements;
    blocks += e.compressed_blocks;
    max_deviation_mm = std::max(max_deviation_mm, e.compress_deviation_mm);
  }
  void print(std::FILE* out) const {
    if (corners > 0)
      std::fprintf(out, "  corner smoothing   %llu corners rounded, deviation from the corner <= %.4f mm\n",
                   static_cast<unsigned long long>(corners), max_corner_deviation_mm);
    if (elements == 0) return;
    std::fprintf(out, "  compressor         %llu blocks into %llu elements, deviation <= %.4f mm\n",
                 static_cast<unsigned long long>(blocks), static_cast<unsigned long long>(elements), max_deviation_mm);
  }
};

}  // namespace

void register_run(CLI::App& app) {
  auto o = std::make_shared<RunOptions>();
  CLI::App* cmd = app.add_subcommand("run", "Plan the program on the machine: time, feed, dips and their causes");
  add_program_options(*cmd, o->program);
  CLI::Option* json_option = cmd->add_option(
      "--json", o->json_file, "Write the JSON report (summary, per-block rows, dips, alarms); - for standard output");
  cmd->add_option("--ndjson", o->ndjson_file, "Write the report as one JSON object per line; - for standard output")
      ->excludes(json_option);
  cmd->add_option("--trace", o->trace_file, "Write one CSV row per IPO cycle");
  cmd->add_option("--dips", o->dips_shown, "Dips listed in the summary")->default_val(10);
  cmd->add_option("--span", o->span,
                  "Time between two events FROM..TO (start, after_m0, after_dwell, contour_start, contour_end, end)");
  cmd->callback([o] {
    install_interrupt_handlers();
    try {
      std::optional<report::RunSpan> span;
      try {
        if (!o->span.empty()) span = report::parse_span(o->span);
      } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
      }
      const machine::MachineProfile profile = load_machine(o->program);
      FilePtr json(nullptr, &std::fclose), trace(nullptr, &std::fclose);
      const bool lines = !o->ndjson_file.empty();
      const std::string& json_path = lines ? o->ndjson_file : o->json_file;
      if (json_path == "-" && o->trace_file == "-") throw UsageError("--json/--ndjson and --trace cannot both be -");
      check_output_path(json_path, o->program.program);
      check_output_path(o->trace_file, o->program.program);
      if (!json_path.empty()) json = open_output(json_path);
      if (!o->trace_file.empty()) trace = open_output(o->trace_file);

      motion::PlanObserver none;
      std::unique_ptr<report::RunReportWriter> report;
      std::unique_ptr<report::TraceCsvWriter> tracer;
      if (json) report = std::make_unique<report::RunReportWriter>(
            json.get(), lines ? report::RunJsonLayout::Lines : report::RunJsonLayout::Document, o->program.program,
            profile.name);
      if (trace) tracer = std::make_unique<report::TraceCsvWriter>(trace.get());
      motion::PlanObserver& a = report ? static_cast<motion::PlanObserver&>(*report) : none;
      motion::PlanObserver& b = tracer ? static_cast<motion::PlanObserver&>(*tracer) : none;
      report::PlanObserverPair outputs(a, b);
      report::RunEventRecorder events(o->program.program);
      report::PlanObserverPair observer(outputs, events);

      motion::PlannerOptions planner_options;
      planner_options.emit_samples = tracer != nullptr;
      motion::Planner planner(profile, observer, planner_options);
      // The end of the last motion the planner receives: the machine position after the run.
      std::optional<motion::Vec3> end_position;
      CompressionTally compression;
      report::ElementTap end_tap(planner, [&end_position, &compression](const interp::PathElement& e) {
        if (e.is_motion() && e.curve) end_position = e.curve->end();
        compression.add(e);
      });
      PipelineOutcome outcome = run_program_tool_centre(o->program, profile, end_tap);
      const motion::PlanSummary& summary = planner.summary();
      const report::RunCompletion completion = report::run_completion(outcome.diagnostics.items(), outcome.alarm);
      if (report) report->finish(summary, outcome.diagnostics, completion, end_position, &events, span);
      if (trace) report::mark_incomplete(trace.get(), completion);
      const bool stdout_taken = json_path == "-" || o->trace_file == "-";
      std::FILE* text_out = stdout_taken ? stderr : stdout;
      print_summary(text_out, *o, profile, summary, completion, report::untimed_cycles(outcome.diagnostics.items()));
      compression.print(text_out);
      if (span) print_span(text_out, events, *span);
      check_written(json.get(), json_path == "-" ? "standard output" : json_path);
      check_written(trace.get(), o->trace_file == "-" ? "standard output" : o->trace_file);
      check_written(stdout, "standard output");
      throw ExitRequest{report_outcome(outcome)};
    } catch (const UsageError& e) {
      std::fprintf(stderr, "drycut run: %s\n", e.what());
      throw ExitRequest{kExitUsage};
    }
  });
}

}  // namespace drycut::app
