// `drycut check PROGRAM`: parses and walks the whole program (expressions evaluated, calls
// followed) without interpreting motion, and reports alarms with their location.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "app/commands.hpp"
#include "app/exit_code.hpp"
#include "app/standard_cycles.hpp"
#include "machine/alarm.hpp"
#include "parser/block.hpp"
#include "parser/program_loader.hpp"

namespace drycut::app {
namespace {

struct CheckOptions {
  std::string program;
  std::vector<std::string> search_path;
  bool no_standard_cycles = false;
  bool json = false;
  uint64_t max_steps = 100'000'000;
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
  parser::LoaderOptions lo;
  lo.search_path = search_path_with_cycles(opt.search_path, !opt.no_standard_cycles);
  lo.max_steps = opt.max_steps;
  Diagnostics diagnostics;
  parser::ProgramLoader loader(lo, diagnostics);
  try {
    loader.open_main(opt.program);
  } catch (const UsageError& e) {
    std::fprintf(stderr, "drycut check: %s\n", e.what());
    return kExitUsage;
  }
  try {
    parser::Block block;
    while (loader.next(block)) {
    }
  } catch (const AlarmError& e) {
    diagnostics.report(e.alarm());
  }
  for (const Alarm& a : diagnostics.items()) std::fprintf(stderr, "%s\n", a.format().c_str());
  const auto commands = loader.commands_used();
  if (opt.json) {
    nlohmann::json j;
    j["program"] = opt.program;
    j["blocks_executed"] = loader.blocks_executed();
    j["lines_executed"] = loader.steps();
    j["programs_used"] = loader.programs_used().size();
    j["programs"] = loader.programs_used();
    j["distinct_commands"] = commands.size();
    j["commands"] = commands;
    j["alarms"] = nlohmann::json::array();
    for (const Alarm& a : diagnostics.items()) j["alarms"].push_back(alarm_json(a));
    std::printf("%s\n", j.dump(2).c_str());
  } else if (!diagnostics.has_alarms()) {
    std::printf("%s: %llu blocks executed, %zu programs used, %zu distinct commands, %zu warnings\n",
                opt.program.c_str(), static_cast<unsigned long long>(loader.blocks_executed()),
                loader.programs_used().size(), commands.size(), diagnostics.warning_count());
  }
  return diagnostics.has_alarms() ? kExitAlarm : kExitOk;
}

}  // namespace

void register_check(CLI::App& app) {
  auto opt = std::make_shared<CheckOptions>();
  CLI::App* cmd = app.add_subcommand("check", "Parse and walk a part program; report alarms");
  cmd->add_option("program", opt->program, "Main program (.MPF)")->required();
  cmd->add_option("--search-path", opt->search_path, "Folder searched for subprograms (repeatable)");
  cmd->add_flag("--no-standard-cycles", opt->no_standard_cycles,
                "Do not search drycut's own standard cycles (CYCLE81 ...) after the search path");
  cmd->add_flag("--json", opt->json, "Print a JSON object instead of the summary line");
  cmd->add_option("--max-steps", opt->max_steps, "Lines executed before an endless-loop alarm")
      ->check(CLI::PositiveNumber);
  cmd->callback([opt] { throw ExitRequest{run_check(*opt)}; });
}

}  // namespace drycut::app
