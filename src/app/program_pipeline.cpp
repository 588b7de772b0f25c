#include "app/program_pipeline.hpp"

#include <cstdio>

#include "app/exit_code.hpp"
#include "app/interruption.hpp"
#include "app/loader_setup.hpp"
#include "interp/controller_state_view.hpp"
#include "app/standard_cycles.hpp"
#include "interp/block_compressor.hpp"
#include "interp/corner_smoothing.hpp"
#include "interp/cutter_compensation.hpp"
#include "interp/cutting_speed_pieces.hpp"
#include "interp/interpreter.hpp"
#include "interp/pipelined_sink.hpp"
#include "machine/tool_table_file.hpp"
#include "parser/program_loader.hpp"
#include "report/progress_display.hpp"

namespace drycut::app {

void add_program_options(CLI::App& cmd, ProgramOptions& options) {
  cmd.add_option("PROGRAM", options.program, "Main program (.MPF)")->required();
  add_run_options(cmd, options);
}

void add_run_options(CLI::App& cmd, ProgramOptions& options) {
  cmd.add_option("--search-path", options.search_path,
                 "Folder searched for subprograms after the main program's folder (repeatable)")
      ->check(CLI::ExistingDirectory);
  cmd.add_option("--definitions", options.definition_dirs,
                 "Folder of definition files (NAME.DEF or _N_NAME_DEF: GUD, macros) or one such file, "
                 "read before the program (repeatable); those beside the main program are always read")
      ->check(CLI::ExistingPath);
  cmd.add_flag("--no-standard-cycles", options.no_standard_cycles,
               "Do not search drycut's own standard cycles (CYCLE81 ...) after the search path");
  cmd.add_option("--machine", options.machine_file,
                 "Machine profile JSON (default: the embedded TAJMAC-ZPS MCV 1210)");
  cmd.add_option("--tools", options.tools_file,
                 "Tool table (.csv or .json) replacing the profile's tools (docs/machine-profile.md)");
  cmd.add_option("--max-steps", options.max_steps,
                 "Blocks executed before the run is stopped as an endless loop")
      ->default_val(options.max_steps);
  cmd.add_flag("-q,--quiet", options.quiet, "No progress display");
  add_missing_programs_option(cmd, options.missing_programs_warn);
}

void add_missing_programs_option(CLI::App& cmd, bool& warn) {
  cmd.add_option_function<std::string>(
         "--missing-programs", [&warn](const std::string& mode) { warn = mode == "warn"; },
         "A called subprogram found in no folder: alarm (default, as the control) or warn")
      ->check(CLI::IsMember({"alarm", "warn"}));
}

machine::MachineProfile load_machine(const ProgramOptions& options) {
  machine::MachineProfile profile;
  try {
    profile = options.machine_file.empty() ? machine::default_profile() : machine::load_profile_file(options.machine_file);
    interp::reset_state(profile);  // a reset code drycut does not know is the profile's error
  } catch (const machine::ProfileError& e) {
    throw UsageError(options.machine_file + ": " + e.what());
  }
  if (!options.tools_file.empty()) {
    try {
      profile.tools = machine::load_tool_table_file(options.tools_file);
    } catch (const machine::ProfileError& e) {
      throw UsageError(e.what());
    }
  }
  return profile;
}

namespace {

// The producer's state as it hands an element to the worker (interp/pipelined_sink.hpp): what an
// alarm raised downstream on that element cuts the run's records back to.
struct ProducerMark {
  size_t diagnostics = 0;
  uint64_t blocks = 0;
  uint64_t lines = 0;
  size_t programs = 0;  // programs_used() so far (the commands used are not cut back: a set)
};

}  // namespace

PipelineOutcome run_program(const ProgramOptions& options, const machine::MachineProfile& profile,
                            interp::ElementSink& sink) {
  PipelineOutcome outcome;
  parser::ProgramLoader loader(make_loader_options(options.search_path, options.max_steps, options.definition_dirs,
                                                   options.missing_programs_warn, !options.no_standard_cycles, profile),
                               outcome.diagnostics);
  loader.open_main(options.program);  // UsageError when the file cannot be read

  // Interpretation on this thread, everything after it on a worker: the same stream, in parallel.
  auto mark = [&] {
    return ProducerMark{outcome.diagnostics.items().size(), loader.blocks_executed(), loader.steps(),
                        loader.programs_used().size()};
  };
  interp::PipelinedSink<ProducerMark, decltype(mark)> pipe(sink, mark);
  interp::Interpreter interpreter(profile, pipe, outcome.diagnostics);
  interp::InterpreterStateView state_view(interpreter, profile);
  loader.set_state_view(&state_view);  // $P_/$AA_/$TC_ reads see the interpreted state
  parser::Block block;
  try {
    // Progress on stderr for long runs, only on a terminal and without --quiet.
    auto progress = report::ProgressDisplay::for_stderr(options.quiet);
    while (loader.next(block)) {
      progress.update(loader.blocks_executed());
      if (interrupt_requested())
        throw AlarmError(make_alarm(990022, "SIGINT or SIGTERM",
                                    SourceLocation{block.file ? *block.file : std::string(), block.line, 0}, block.text));
      interpreter.execute(block);
      if (interpreter.ended()) break;
    }
  } catch (const AlarmError& e) {
    // The elements already handed over come from earlier blocks: an alarm they raise came first.
    pipe.drain();
    if (!pipe.failure()) outcome.diagnostics.report(e.alarm());
    outcome.alarm = true;
  }
  try {
    // After an alarm this still hands the sinks what they hold, so nothing written is lost.
    interpreter.finish();
  } catch (const AlarmError& e) {
    // The control stops at the first alarm: one raised while finishing after it is a follow-up,
    // and so is one after an element still in the pipe that raises downstream.
    pipe.drain();
    if (!outcome.alarm && !pipe.failure()) outcome.diagnostics.report(e.alarm());
    outcome.alarm = true;
  }
  // The worker has consumed all it was given (finishing may have stopped before handing over the
  // rest): what failed downstream is settled from here on.
  pipe.drain();
  outcome.blocks = loader.blocks_executed();
  outcome.lines = loader.steps();
  if (const auto& failure = pipe.failure()) {
    // Stopped downstream: the run ends at that element's block, as run sequentially; what the
    // interpreter did ahead of it (its warnings, its blocks) did not happen.
    outcome.diagnostics.truncate(failure->mark.diagnostics);
    outcome.diagnostics.report(failure->error.alarm());
    outcome.alarm = true;
    outcome.blocks = failure->mark.blocks;
    outcome.lines = failure->mark.lines;
  }
  outcome.programs_used = loader.programs_used();
  if (const auto& failure = pipe.failure(); failure && failure->mark.programs < outcome.programs_used.size())
    outcome.programs_used.resize(failure->mark.programs);
  outcome.commands_used = loader.commands_used();
  return outcome;
}

PipelineOutcome run_program_tool_centre(const ProgramOptions& options, const machine::MachineProfile& profile,
                                        interp::ElementSink& sink) {
  Diagnostics compensation_diagnostics;
  interp::CuttingSpeedPieces pieces(sink);
  interp::CornerSmoothing smoothing(pieces, profile);
  interp::BlockCompressor compressor(smoothing, profile);
  interp::CutterCompensation compensation(compressor, profile, compensation_diagnostics);
  PipelineOutcome outcome = run_program(options, profile, compensation);
  for (const auto& a : compensation_diagnostics.items()) outcome.diagnostics.report(a);
  return outcome;
}

int report_outcome(const PipelineOutcome& outcome) {
  for (const Alarm& a : outcome.diagnostics.items()) std::fprintf(stderr, "%s\n", a.format().c_str());
  return outcome.alarm || outcome.diagnostics.has_alarms() ? kExitAlarm : kExitOk;
}

}  // namespace drycut::app
