#pragma once
// Runs a part program through loader -> interpreter -> a sink (path writer, planner), and turns
// what happened into the exit-code contract: alarms and warnings on stderr, 0/1/2.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "interp/path_element.hpp"
#include "machine/alarm.hpp"
#include "machine/machine_profile.hpp"

namespace drycut::app {

struct ProgramOptions {
  std::string program;
  std::vector<std::string> search_path;
  bool no_standard_cycles = false; // true: drycut's own cycles (programs/cycles) are not searched
  std::string machine_file;        // empty = embedded default profile
  uint64_t max_steps = 100'000'000;
  bool quiet = false;              // no progress display
};

// Adds PROGRAM, --search-path, --no-standard-cycles, --machine, --max-steps to a subcommand.
void add_program_options(CLI::App& cmd, ProgramOptions& options);

// Loads the machine profile named by the options (UsageError on a bad file).
machine::MachineProfile load_machine(const ProgramOptions& options);

struct PipelineOutcome {
  Diagnostics diagnostics;
  bool alarm = false;              // the run ended in an alarm
  uint64_t blocks = 0;             // blocks executed
  std::vector<std::string> programs_used;
};

// Streams the program into the sink. Alarms end the run (the sink has received everything up to
// the alarm and is finished, so nothing already written is lost). Throws UsageError for I/O.
PipelineOutcome run_program(const ProgramOptions& options, const machine::MachineProfile& profile,
                            interp::ElementSink& sink);

// The same through the tool radius compensation stage: the sink receives the tool-centre path,
// and the stage's warnings (10763 ...) join the outcome's diagnostics.
PipelineOutcome run_program_tool_centre(const ProgramOptions& options, const machine::MachineProfile& profile,
                                        interp::ElementSink& sink);

// Prints warnings and alarms on stderr and returns the exit code (0 clean, 1 alarms).
int report_outcome(const PipelineOutcome& outcome);

}  // namespace drycut::app
