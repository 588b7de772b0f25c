// `drycut path PROGRAM [--csv FILE] [--step MM]`: the interpolated programmed path as CSV.
#include <cstdio>
#include <memory>

#include "app/commands.hpp"
#include "app/exit_code.hpp"
#include "app/interruption.hpp"
#include "app/output_file.hpp"
#include "app/program_pipeline.hpp"
#include "report/element_listing.hpp"
#include "report/path_csv_writer.hpp"
#include "report/run_completion.hpp"

namespace drycut::app {

namespace {
struct PathOptions {
  ProgramOptions program;
  std::string csv;
  double step_mm = 0.01;
  bool elements = false;
  bool tool_centre = false;
};
}  // namespace

void register_path(CLI::App& app) {
  auto options = std::make_shared<PathOptions>();
  CLI::App* cmd = app.add_subcommand("path", "Write the interpolated programmed path as CSV samples");
  add_program_options(*cmd, options->program);
  cmd->add_option("--csv", options->csv, "Output file (default: standard output)");
  cmd->add_option("--step", options->step_mm, "Sample spacing along the path in mm")
      ->default_val(0.01)
      ->check(CLI::PositiveNumber);
  cmd->add_flag("--tool-centre", options->tool_centre,
                "The tool-centre path (after G41/G42 radius compensation) instead of the programmed one");
  cmd->add_flag("--elements", options->elements,
                "List the element stream (what the interpreter hands the planner) instead of samples");
  cmd->callback([options] {
    install_interrupt_handlers();
    try {
      const machine::MachineProfile profile = load_machine(options->program);
      std::FILE* out = stdout;
      std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(nullptr, &std::fclose);
      if (!options->csv.empty()) {
        check_output_path(options->csv, options->program.program);
        file.reset(std::fopen(options->csv.c_str(), "w"));
        if (!file) throw UsageError("cannot write " + options->csv);
        out = file.get();
      }
      std::unique_ptr<interp::ElementSink> writer;
      if (options->elements) writer = std::make_unique<report::ElementListingWriter>(out);
      else writer = std::make_unique<report::PathCsvWriter>(out, options->step_mm);
      PipelineOutcome outcome = options->tool_centre ? run_program_tool_centre(options->program, profile, *writer)
                                                     : run_program(options->program, profile, *writer);
      report::mark_incomplete(out, report::run_completion(outcome.diagnostics.items(), outcome.alarm));
      check_written(out, options->csv.empty() ? "standard output" : options->csv);
      throw ExitRequest{report_outcome(outcome)};
    } catch (const UsageError& e) {
      std::fprintf(stderr, "drycut path: %s\n", e.what());
      throw ExitRequest{kExitUsage};
    }
  });
}

}  // namespace drycut::app
