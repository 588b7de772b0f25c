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
#include "parser/program_loader.hpp"

namespace drycut::app {

struct ProgramOptions {
  std::string program;
  std::vector<std::string> search_path;
  std::vector<std::string> definition_dirs;  // GUD/MAC definition files (.DEF)
  bool no_standard_cycles = false; // true: drycut's own cycles (programs/cycles) are not searched
  std::string machine_file;        // empty = embedded default profile
  std::string tools_file;          // empty = the profile's tool table; else it replaces it
  uint64_t max_steps = 100'000'000;
  bool quiet = false;              // no progress display
  bool missing_programs_warn = false;  // --missing-programs warn: a call of a missing program warns
};

// Adds PROGRAM, --search-path, --definitions, --no-standard-cycles, --machine, --tools,
// --max-steps, --missing-programs to a subcommand.
void add_program_options(CLI::App& cmd, ProgramOptions& options);
// The same options without PROGRAM, for commands that run many programs (regress).
void add_run_options(CLI::App& cmd, ProgramOptions& options);

// `--missing-programs alarm|warn` (default alarm): whether calling a subprogram that is in no
// searched folder stops the run with the control's alarm, or only warns (for programs checked
// without all of the machine's cycles at hand).
void add_missing_programs_option(CLI::App& cmd, bool& warn);

// Loads the machine profile named by the options, with the --tools table in place of the
// profile's (UsageError on a bad file).
machine::MachineProfile load_machine(const ProgramOptions& options);

struct PipelineOutcome {
  Diagnostics diagnostics;
  bool alarm = false;              // the run ended in an alarm
  uint64_t blocks = 0;             // blocks executed
  uint64_t lines = 0;              // lines executed, including consumed ones (jumps, DEF ...)
  std::vector<std::string> programs_used;
  std::vector<std::string> commands_used;  // distinct G/M words and commands, sorted
};

// Streams the program into the sink. Alarms end the run (the sink has received everything up to
// the alarm and is finished, so nothing already written is lost). Throws UsageError for I/O.
PipelineOutcome run_program(const ProgramOptions& options, const machine::MachineProfile& profile,
                            interp::ElementSink& sink);

// The same through the tool radius compensation stage and the NC block compressor
// (COMPON/COMPCURV/COMPCAD): the sink receives the tool-centre path as the planner gets it, and
// the compensation's warnings (10763 ...) join the outcome's diagnostics.
PipelineOutcome run_program_tool_centre(const ProgramOptions& options, const machine::MachineProfile& profile,
                                        interp::ElementSink& sink);

// Prints warnings and alarms on stderr and returns the exit code (0 clean, 1 alarms).
int report_outcome(const PipelineOutcome& outcome);

}  // namespace drycut::app
