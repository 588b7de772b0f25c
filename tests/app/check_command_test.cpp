// The `drycut check` command-line contract: exit codes 0/1/2, the summary line, --json,
// --search-path, --definitions, --max-steps.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "cli_support.hpp"

namespace {

namespace fs = std::filesystem;

using drycut::testing::CliRun;

CliRun run(const std::string& args, bool with_stderr = false) {
  return drycut::testing::run_shell(drycut::testing::drycut_command("check " + args) +
                                    (with_stderr ? " 2>&1" : " 2>/dev/null"));
}

class CheckCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("drycut_check_cli_" + std::to_string(::getpid()));
    fs::create_directories(dir_ / "subs");
    write("MAIN.MPF", "N10 G1 X1 F100\nN20 SOFT\nN30 ekvi_sub P2\nN40 CUT3DC\nN50 M30\n");
    write("subs/EKVI_SUB.SPF", "G1 Y1\nM17\n");
  }
  void TearDown() override { fs::remove_all(dir_); }
  void write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name, std::ios::binary) << text;
  }
  std::string path(const std::string& name) const { return "'" + (dir_ / name).string() + "'"; }
  fs::path dir_;
};

TEST_F(CheckCommand, CleanProgramExitsZeroWithSummary) {
  const CliRun r = run(path("MAIN.MPF") + " --search-path " + path("subs"));
  EXPECT_EQ(r.exit_code, 0);
  // Blocks: N10, N20, 2 x (G1 Y1, M17), N50 = 7 (CUT3DC alone is not modelled: dropped).
  EXPECT_NE(r.out.find("7 blocks executed"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("2 programs used"), std::string::npos) << r.out;
}

TEST_F(CheckCommand, NotModelledCommandIsAWarningNotAnAlarm) {
  const CliRun r = run(path("MAIN.MPF") + " --search-path " + path("subs"), true);
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find(":4:5: WARNING 990002"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("CUT3DC"), std::string::npos);
}

TEST_F(CheckCommand, JsonOutputCarriesCountsAndAlarms) {
  const CliRun r = run(path("MAIN.MPF") + " --search-path " + path("subs") + " --json");
  EXPECT_EQ(r.exit_code, 0);
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["blocks_executed"], 7);
  EXPECT_EQ(j["programs_used"], 2);
  // G1, M17, M30, SOFT
  EXPECT_EQ(j["distinct_commands"], 4);
  ASSERT_EQ(j["alarms"].size(), 1u);
  EXPECT_EQ(j["alarms"][0]["number"], 990002);
  EXPECT_EQ(j["alarms"][0]["severity"], "warning");
  EXPECT_EQ(j["alarms"][0]["line"], 4);
}

TEST_F(CheckCommand, MissingSubprogramWithoutSearchPathIsAlarmExitOne) {
  const CliRun r = run(path("MAIN.MPF"), true);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.out.find("MAIN.MPF:3:5: ALARM 14011"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("| N30 ekvi_sub P2"), std::string::npos) << r.out;
}

TEST_F(CheckCommand, JsonListsTheAlarm) {
  const CliRun r = run(path("MAIN.MPF") + " --json");
  EXPECT_EQ(r.exit_code, 1);
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_FALSE(j["alarms"].empty());
  EXPECT_EQ(j["alarms"].back()["number"], 14011);
  EXPECT_EQ(j["alarms"].back()["line"], 3);
  EXPECT_EQ(j["alarms"].back()["column"], 5);
}

// `--missing-programs alarm` is the control's behaviour and the default; other values are usage
// errors. The same option is on run, path and report.
TEST_F(CheckCommand, MissingProgramsAlarmIsTheDefaultBehaviour) {
  const CliRun r = run(path("MAIN.MPF") + " --missing-programs alarm", true);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.out.find("MAIN.MPF:3:5: ALARM 14011"), std::string::npos) << r.out;
  EXPECT_EQ(run(path("MAIN.MPF") + " --missing-programs maybe").exit_code, 2);
  for (const char* command : {"run", "path", "report -o /dev/null"}) {
    const CliRun other = drycut::testing::run_shell(drycut::testing::drycut_command(
        std::string(command) + " -q " + path("MAIN.MPF") + " --missing-programs alarm 2>&1 >/dev/null"));
    EXPECT_EQ(other.exit_code, 1) << command << ": " << other.out;
    EXPECT_NE(other.out.find("ALARM 14011"), std::string::npos) << command << ": " << other.out;
    EXPECT_EQ(drycut::testing::run_shell(drycut::testing::drycut_command(std::string(command) + " -q " +
                                                                         path("MAIN.MPF") +
                                                                         " --missing-programs maybe 2>/dev/null"))
                  .exit_code,
              2)
        << command;
  }
}

// `--missing-programs warn`: warning 14011 once per missing name, the call skipped, the
// program goes on to its end (the blocks after the call run).
TEST_F(CheckCommand, MissingProgramsWarnSkipsTheCallOncePerName) {
  write("WARN.MPF", "G0 X0 Y0 Z0\nOEM_PROBE(1, 2)\nOEM_PROBE(3, 4)\nG0 X5\nM30\n");
  const CliRun r = run(path("WARN.MPF") + " --missing-programs warn --json", true);
  EXPECT_EQ(r.exit_code, 0) << r.out;
  const size_t first = r.out.find("WARNING 14011");
  ASSERT_NE(first, std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("WARNING 14011", first + 1), std::string::npos) << "one warning per name: " << r.out;
  EXPECT_NE(r.out.find("\"blocks_executed\": 3"), std::string::npos) << r.out;  // G0, G0 X5, M30
}

TEST_F(CheckCommand, MissingMainFileIsUsageErrorExitTwo) {
  EXPECT_EQ(run(path("NOPE.MPF")).exit_code, 2);
}

TEST_F(CheckCommand, BadFlagIsUsageErrorExitTwo) {
  EXPECT_EQ(run(path("MAIN.MPF") + " --no-such-flag").exit_code, 2);
  EXPECT_EQ(run("").exit_code, 2);
}

// A folder or file named on the command line that does not exist is a usage error (exit 2):
// before 2026-11-29 it was ignored, and a typo in a definition folder showed up later as
// alarms about undefined names in a program that is correct.
TEST_F(CheckCommand, NonexistentSearchPathOrDefinitionsIsUsageError) {
  const CliRun s = run(path("MAIN.MPF") + " --search-path " + path("no_such_folder"), true);
  EXPECT_EQ(s.exit_code, 2) << s.out;
  EXPECT_NE(s.out.find("no_such_folder"), std::string::npos) << s.out;
  const CliRun d = run(path("MAIN.MPF") + " --search-path " + path("subs") + " --definitions " + path("NO.DEF"), true);
  EXPECT_EQ(d.exit_code, 2) << d.out;
  EXPECT_NE(d.out.find("NO.DEF"), std::string::npos) << d.out;
}

// GUD definitions come as NAME.DEF or under the control's own file name _N_NAME_DEF (as in an
// archive of the NC's data), beside the program or in a --definitions folder; --definitions
// may also name one file, whatever its name.
TEST_F(CheckCommand, DefinitionFilesByControlNameOrNamedFile) {
  write("GUD.MPF", "IF (_TOOL_MAX<>12) OR (_FEED_MAX<>3000) GOTOF FAIL\nG1 X1 F100\nM30\nFAIL: SETAL(65000)\nM30\n");
  const CliRun undefined = run(path("GUD.MPF"));
  EXPECT_EQ(undefined.exit_code, 1) << "without the definitions the names are unknown: " << undefined.out;
  write("_N_UGUD_DEF", "%_N_UGUD_DEF\n;$PATH=/_N_DEF_DIR\nDEF NCK INT _TOOL_MAX=12\nM30\n");
  fs::create_directories(dir_ / "machine");
  write("machine/feeds.txt", "DEF CHAN REAL _FEED_MAX=3000\nM30\n");
  const CliRun r = run(path("GUD.MPF") + " --definitions " + path("machine/feeds.txt"), true);
  EXPECT_EQ(r.exit_code, 0) << r.out;
  fs::create_directories(dir_ / "gud");
  fs::rename(dir_ / "_N_UGUD_DEF", dir_ / "gud" / "_n_ugud_def");  // any case, in a --definitions folder
  const CliRun folder = run(path("GUD.MPF") + " --definitions " + path("gud") + " --definitions " +
                            path("machine/feeds.txt"), true);
  EXPECT_EQ(folder.exit_code, 0) << folder.out;
}

TEST_F(CheckCommand, MaxStepsTurnsAnEndlessLoopIntoAnAlarm) {
  write("LOOP.MPF", "LOOP\nG1 X1 F100\nENDLOOP\n");
  const CliRun r = run(path("LOOP.MPF") + " --max-steps 100", true);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.out.find("ALARM 990004"), std::string::npos) << r.out;
}

}  // namespace
