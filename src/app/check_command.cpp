// `drycut check PROGRAM`: reads and interprets the whole program as `run` does (expressions
// evaluated, calls, jumps and loops followed, every block interpreted, tool radius compensation
// applied) without planning the motion, and reports alarms with their location.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "app/commands.hpp"
#include "app/exit_code.hpp"
#include "app/interruption.hpp"
#include "app/program_pipeline.hpp"
#include "interp/path_element.hpp"
#include "machine/alarm.hpp"

namespace drycut::app {
namespace {

struct CheckOptions {
  ProgramOptions program;
  bool json = false;
};

// Takes the elements and drops them: `check` interprets (and compensates) but does not plan.
class DiscardingSink : public interp::ElementSink {
 public:
  void consume(interp::PathElement&&) override {}
};

nlohmann::json alarm_json(const Alarm& a) {
  return {{"number", a.number},
          {"severity", a.severity == Severity::Warning ? "warning" : "alarm"},
          {"text", a.text},
          {"file", a.where.file},
          {"line", a.where.line},
          {"column", a.where.column},
          {"block", a.block}};
}

int run_check(const CheckOptions& opt) {
  // The same pipeline as `run` up to the planner: one language, one interpreter, one machine,
  // so `check` accepts and refuses what `run` does (alarms of the planner itself excepted).
  PipelineOutcome outcome;
  try {
    const machine::MachineProfile profile = load_machine(opt.program);
    DiscardingSink sink;
    outcome = run_program_tool_centre(opt.program, profile, sink);
  } catch (const UsageError& e) {
    std::fprintf(stderr, "drycut check: %s\n", e.what());
    return kExitUsage;
  }
  const Diagnostics& diagnostics = outcome.diagnostics;
  for (const Alarm& a : diagnostics.items()) std::fprintf(stderr, "%s\n", a.format().c_str());
  const auto& commands = outcome.commands_used;
  if (opt.json) {
    nlohmann::json j;
    j["program"] = opt.program.program;
    j["blocks_executed"] = outcome.blocks;
    j["lines_executed"] = outcome.lines;
    j["programs_used"] = outcome.programs_used.size();
    j["programs"] = outcome.programs_used;
    j["distinct_commands"] = commands.size();
    j["commands"] = commands;
    j["alarms"] = nlohmann::json::array();
    for (const Alarm& a : diagnostics.items()) j["alarms"].push_back(alarm_json(a));
    std::printf("%s\n", j.dump(2).c_str());
  } else if (!diagnostics.has_alarms() && !outcome.alarm) {
    std::printf("%s: %llu blocks executed, %zu programs used, %zu distinct commands, %zu warnings\n",
                opt.program.program.c_str(), static_cast<unsigned long long>(outcome.blocks),
                outcome.programs_used.size(), commands.size(), diagnostics.warning_count());
  }
  return outcome.alarm || diagnostics.has_alarms() ? kExitAlarm : kExitOk;
}

}  // namespace

void register_check(CLI::App& app) {
  auto opt = std::make_shared<CheckOptions>();
  CLI::App* cmd = app.add_subcommand("check", "Interpret a part program without planning it; report alarms");
  add_program_options(*cmd, opt->program);
  cmd->add_flag("--json", opt->json, "Print a JSON object instead of the summary line");
  cmd->callback([opt] {
    install_interrupt_handlers();
    throw ExitRequest{run_check(*opt)};
  });
}

}  // namespace drycut::app
