// Ctrl-C during a run (app/interruption.hpp): the run stops before its next block with alarm
// 990022, the JSON report is finished (valid, complete false, stopped_at that block) and the exit
// code is 1, as for an alarm. The program is a counted loop of moves that would run ~100 M steps.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "report_cli_support.hpp"

namespace {

using namespace drycut::report_cli;

TEST(InterruptedRun, SigintStopsAtABlockAndFinishesTheReport) {
  TempDir dir("drycut_interrupted");
  const auto program = dir.path / "LONG.MPF";
  write_file(program, "G90 G94 F20000\nR1=0\nSTART:\nG1 X=R1 MOD 50\nR1=R1+1\nIF R1<100000000 GOTOB START\nM30\n");
  const auto json = dir.path / "run.json";
  const auto err = dir.path / "stderr.txt";
  // --preserve-status: the exit code is drycut's own, not timeout's 124. --foreground: timeout
  // signals drycut alone; without it, it signals drycut and then its whole process group, and a
  // second SIGINT that arrives after the first was handled takes the default action (the handler
  // is SA_RESETHAND: a second Ctrl-C ends the process), exit 130 with the report cut short — a
  // flaky failure on a loaded machine.
  const CliRun r = drycut::testing::run_shell("timeout --foreground --preserve-status -s INT 0.5 " +
                                              drycut::testing::drycut_command("run -q --json " + quoted(json) + " " +
                                                                              quoted(program)) +
                                              " 2>" + quoted(err) + " >/dev/null");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(read_file(err).find("ALARM 990022"), std::string::npos) << read_file(err);
  const auto report = nlohmann::json::parse(read_file(json));
  EXPECT_FALSE(report["summary"]["complete"].get<bool>());
  EXPECT_EQ(report["summary"]["stopped_at"]["alarm"].get<int>(), 990022);
  EXPECT_GT(report["summary"]["time_s"].get<double>(), 0.0);
}

}  // namespace
