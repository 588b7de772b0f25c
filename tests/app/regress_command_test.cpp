// `drycut regress` end to end: the baseline is written with relative keys for main programs only
// (the called .SPF is not run on its own), an unchanged run passes, a program made slower (the
// same contour at half the feed: the 150 mm of cutting take 9 s at F1000 and 18 s at F500, far
// beyond the 2 % time tolerance) fails with exit 1, a table naming it and a JUnit failure, an
// added alarm fails, a new program fails, a missing baseline is a usage error, and the figures
// do not depend on the number of parallel jobs.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <regex>

#include "report_cli_support.hpp"

namespace {

using namespace drycut::report_cli;
using nlohmann::json;

// Cuts 5 + 100 + 50 mm at F (the last 100 + 50 in a subprogram and back) after a 95 mm G0.
std::string part(int feed) {
  return "G90 G17 G54 G64\nG0 X0 Y0 Z5\nG1 Z0 F" + std::to_string(feed) + "\nSIDE\nG1 Y50\nM30\n";
}
constexpr const char* kSide = "G1 X100\nM17\n";
constexpr const char* kOther = "G0 X0 Y0 Z5\nG1 X10 F600\nG1 Y10\nM30\n";
// kOther with a circle whose end point is not on it (centre (5,10) r 5, end (0,0) 11.18 mm from the centre): alarm 14040.
constexpr const char* kOtherWithAlarm = "G0 X0 Y0 Z5\nG1 X10 F600\nG1 Y10\nG2 X0 Y0 I-5 J0\nM30\n";

class Regress : public ::testing::Test {
 protected:
  Regress() : dir_("drycut_regress") {
    fs::create_directories(dir_.path / "progs" / "deep");
    write_file(dir_.path / "progs" / "PART.MPF", part(1000));
    write_file(dir_.path / "progs" / "SIDE.SPF", kSide);
    write_file(dir_.path / "progs" / "deep" / "OTHER.MPF", kOther);
  }
  CliRun regress(const std::string& args) {
    return drycut::testing::run_shell("cd " + quoted(dir_.path) + " && " +
                                      drycut::testing::drycut_command("regress -q " + args) + " 2>&1");
  }
  fs::path path(const std::string& rel) const { return dir_.path / rel; }
  TempDir dir_;
};

TEST_F(Regress, WritesTheBaselineWithRelativeKeysOfMainPrograms) {
  const CliRun r = regress("progs --baseline base.json --update");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const json b = json::parse(read_file(path("base.json")));
  ASSERT_EQ(b["programs"].size(), 2u) << b.dump(2);
  ASSERT_TRUE(b["programs"].contains("progs/PART.MPF")) << b.dump(2);
  ASSERT_TRUE(b["programs"].contains("progs/deep/OTHER.MPF")) << b.dump(2);
  const json& p = b["programs"]["progs/PART.MPF"];
  EXPECT_NEAR(p["path_length_mm"].get<double>(), 95 + 5 + 100 + 50, 1e-4);
  EXPECT_GT(p["time_s"].get<double>(), 155.0 / 1000 * 60);  // never faster than F
  EXPECT_TRUE(p["complete"].get<bool>());
  EXPECT_TRUE(p["alarms"].empty());
  // The run's own JSON agrees on every figure the baseline keeps.
  const CliRun run = drycut::testing::run_shell(
      drycut::testing::drycut_command("run -q " + quoted(path("progs/PART.MPF")) + " --json -") + " 2>/dev/null");
  const json s = json::parse(run.out)["summary"];
  EXPECT_NEAR(p["time_s"].get<double>(), s["time_s"].get<double>(), 1e-4);
  EXPECT_NEAR(p["min_feed_mm_min"].get<double>(), s["min_feed_mm_min"].get<double>(), 1e-3);
  EXPECT_EQ(p["dips"], s["dips"]);
}

TEST_F(Regress, UnchangedRunPasses) {
  ASSERT_EQ(regress("progs --baseline base.json --update").exit_code, 0);
  const CliRun r = regress("progs --baseline base.json --junit out.xml");
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("2 programs, 0 changed"), std::string::npos) << r.out;
  const std::string xml = read_file(path("out.xml"));
  EXPECT_NE(xml.find("tests=\"2\" failures=\"0\""), std::string::npos) << xml;
  EXPECT_EQ(xml.find("<failure"), std::string::npos) << xml;
}

TEST_F(Regress, ASlowerProgramFailsWithATableAndAJUnitFailure) {
  ASSERT_EQ(regress("progs --baseline base.json --update").exit_code, 0);
  write_file(path("progs/PART.MPF"), part(500));
  const CliRun r = regress("progs --baseline base.json --junit out.xml");
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_TRUE(std::regex_search(r.out, std::regex(R"(progs/PART\.MPF +time +[0-9.]+ s +[0-9.]+ s +\+[0-9.]+ %)")))
      << r.out;
  EXPECT_NE(r.out.find("1 changed"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("OTHER.MPF"), std::string::npos) << "only the changed program is listed\n" << r.out;
  const std::string xml = read_file(path("out.xml"));
  EXPECT_NE(xml.find("tests=\"2\" failures=\"1\""), std::string::npos) << xml;
  EXPECT_TRUE(std::regex_search(
      xml, std::regex(R"(<testcase name="progs/PART\.MPF" classname="drycut\.regress\.progs" time="[0-9.]+">\s*<failure message="time )")))
      << xml;
  // Accepting the change makes the next run pass.
  ASSERT_EQ(regress("progs --baseline base.json --update").exit_code, 0);
  EXPECT_EQ(regress("progs --baseline base.json").exit_code, 0);
}

TEST_F(Regress, AnAddedAlarmFails) {
  ASSERT_EQ(regress("progs --baseline base.json --update").exit_code, 0);
  write_file(path("progs/deep/OTHER.MPF"), kOtherWithAlarm);
  const CliRun r = regress("progs --baseline base.json --junit out.xml");
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_TRUE(std::regex_search(r.out, std::regex(R"(progs/deep/OTHER\.MPF +alarm +- +14040 at OTHER\.MPF:4 +new)")))
      << r.out;
  EXPECT_NE(read_file(path("out.xml")).find("alarm - -&gt; 14040 at OTHER.MPF:4"), std::string::npos)
      << read_file(path("out.xml"));
}

TEST_F(Regress, NewAndMissingProgramsFail) {
  ASSERT_EQ(regress("progs --baseline base.json --update").exit_code, 0);
  write_file(path("progs/NEW.MPF"), kOther);
  const CliRun added = regress("progs --baseline base.json");
  EXPECT_EQ(added.exit_code, 1) << added.out;
  EXPECT_NE(added.out.find("progs/NEW.MPF"), std::string::npos) << added.out;
  fs::remove(path("progs/NEW.MPF"));
  const CliRun subset = regress("progs/PART.MPF --baseline base.json");
  EXPECT_EQ(subset.exit_code, 1) << subset.out;
  EXPECT_NE(subset.out.find("missing program"), std::string::npos) << subset.out;
}

TEST_F(Regress, GlobsFoldersAndJobsGiveTheSameBaseline) {
  ASSERT_EQ(regress("progs --baseline one.json --update --jobs 1").exit_code, 0);
  ASSERT_EQ(regress("'progs/**/*.MPF' --baseline two.json --update --jobs 4").exit_code, 0);
  EXPECT_EQ(read_file(path("one.json")), read_file(path("two.json")));
  EXPECT_EQ(regress("'progs/*.MPF' 'progs/deep/*.MPF' --baseline one.json --jobs 2").exit_code, 0);
}

TEST_F(Regress, UsageErrors) {
  EXPECT_EQ(regress("progs --baseline absent.json").exit_code, 2);
  EXPECT_EQ(regress("nowhere --baseline base.json --update").exit_code, 2);
  EXPECT_EQ(regress("'progs/*.NONE' --baseline base.json --update").exit_code, 2);
  EXPECT_EQ(regress("progs --baseline base.json --update --tolerance speed=3%").exit_code, 2);
  write_file(path("notabaseline.json"), "{\"programs\": {}}");
  EXPECT_EQ(regress("progs --baseline notabaseline.json").exit_code, 2);
}

TEST_F(Regress, AWiderToleranceAcceptsTheSlowerProgram) {
  ASSERT_EQ(regress("progs --baseline base.json --update").exit_code, 0);
  write_file(path("progs/PART.MPF"), part(900));
  // F1000 -> F900: the 150 mm of cutting take 1 s longer, about +10 %; the corner feed may move too.
  EXPECT_EQ(regress("progs --baseline base.json").exit_code, 1);
  const CliRun wide = regress("progs --baseline base.json --tolerance time=20%,feed=20%,dips=5");
  EXPECT_EQ(wide.exit_code, 0) << wide.out;
}

}  // namespace
