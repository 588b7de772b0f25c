// `drycut compare`: its figures equal the individual runs' summaries; program size counts the
// subprograms; JSON and HTML outputs.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "report_cli_support.hpp"

namespace {

using namespace drycut::report_cli;
using nlohmann::json;

TEST(CompareCommand, FiguresEqualTheIndividualRuns) {
  TempDir dir("drycut_compare_cli");
  write_file(dir.path / "SQUARE.MPF",
             "N10 G0 X0 Y0\nN20 G1 X20 F2000\nN30 Y20\nN40 X0\nN50 Y0\nN60 M0\nN70 G1 X5 Y5\nN80 M30\n");
  write_file(dir.path / "ROUND.MPF", "N10 G0 X10 Y0\nN20 G64 F3000\nN30 ROUND_SUB\nN40 M30\n");
  write_file(dir.path / "ROUND_SUB.SPF", "G2 X-10 Y0 I-10 J0\nG2 X10 Y0 I10 J0\nG1 X12 Y2\nM17\n");
  const fs::path out_json = dir.path / "cmp.json", out_html = dir.path / "cmp.html";
  const CliRun r = run_drycut("compare " + quoted(dir.path / "SQUARE.MPF") + " " + quoted(dir.path / "ROUND.MPF") +
                          " --json " + quoted(out_json) + " --html " + quoted(out_html));
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("SQUARE.MPF"), std::string::npos);
  EXPECT_NE(r.out.find("ROUND.MPF"), std::string::npos);
  const json cmp = json::parse(read_file(out_json));
  ASSERT_EQ(cmp["programs"].size(), 2u);

  const char* names[] = {"SQUARE.MPF", "ROUND.MPF"};
  for (size_t i = 0; i < 2; ++i) {
    const fs::path run_json = dir.path / (std::string("run") + std::to_string(i) + ".json");
    ASSERT_EQ(run_drycut("run " + quoted(dir.path / names[i]) + " --json " + quoted(run_json)).exit_code, 0);
    const json s = json::parse(read_file(run_json))["summary"];
    const json& c = cmp["programs"][i];
    EXPECT_EQ(c["time_s"].get<double>(), s["time_s"].get<double>()) << names[i];
    EXPECT_EQ(c["time_after_m0_s"].get<double>(), s["time_after_m0_s"].get<double>()) << names[i];
    EXPECT_EQ(c["min_feed_mm_min"].get<double>(), s["min_feed_mm_min"].get<double>()) << names[i];
    EXPECT_EQ(c["path_length_mm"].get<double>(), s["path_length_mm"].get<double>()) << names[i];
    EXPECT_EQ(c["dips"].get<size_t>(), s["dips"].get<size_t>()) << names[i];
    EXPECT_TRUE(c["max_deviation_mm"].is_null());
  }
  // Hand-checked: the square has an M0, so time after M0 is positive but below the total.
  EXPECT_GT(cmp["programs"][0]["time_after_m0_s"].get<double>(), 0.0);
  EXPECT_LT(cmp["programs"][0]["time_after_m0_s"].get<double>(), cmp["programs"][0]["time_s"].get<double>());
  // Size: the main program alone, and main plus the subprogram it calls.
  EXPECT_EQ(cmp["programs"][0]["program_bytes"].get<uint64_t>(), fs::file_size(dir.path / "SQUARE.MPF"));
  EXPECT_EQ(cmp["programs"][1]["program_bytes"].get<uint64_t>(),
            fs::file_size(dir.path / "ROUND.MPF") + fs::file_size(dir.path / "ROUND_SUB.SPF"));

  const std::string page = read_file(out_html);
  EXPECT_NE(page.find("<svg id=\"compare-paths\""), std::string::npos);
  EXPECT_NE(page.find("ROUND.MPF"), std::string::npos);
  EXPECT_EQ(page.find("http://"), std::string::npos);
  EXPECT_EQ(page.find("https://"), std::string::npos);
}

TEST(CompareCommand, MaxDeviationWithAReference) {
  TempDir dir("drycut_compare_cli_dev");
  write_file(dir.path / "C10.MPF", "N10 G0 X10 Y0\nN20 G2 X10 Y0 I-10 J0 F1200\nN30 M30\n");
  write_file(dir.path / "C11.MPF", "N10 G0 X10.2 Y0\nN20 G2 X10.2 Y0 I-10.2 J0 F1200\nN30 M30\n");
  const fs::path out_json = dir.path / "cmp.json";
  ASSERT_EQ(run_drycut("compare " + quoted(dir.path / "C10.MPF") + " " + quoted(dir.path / "C11.MPF") +
                   " --polar 10.03 --json " + quoted(out_json))
                .exit_code,
            0);
  const json cmp = json::parse(read_file(out_json));
  // Radial gaps |10 - 10.03| and |10.2 - 10.03| (closed form), within the polyline sag.
  EXPECT_NEAR(cmp["programs"][0]["max_deviation_mm"].get<double>(), 0.03, 1e-5);
  EXPECT_NEAR(cmp["programs"][1]["max_deviation_mm"].get<double>(), 0.17, 1e-5);
}

TEST(CompareCommand, AlarmInOneProgramExitsOne) {
  TempDir dir("drycut_compare_cli_alarm");
  write_file(dir.path / "OK.MPF", "G1 X1 F100\nM30\n");
  write_file(dir.path / "BAD.MPF", "G1 QQ=5\nM30\n");
  const CliRun r = run_drycut("compare " + quoted(dir.path / "OK.MPF") + " " + quoted(dir.path / "BAD.MPF"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.out.find("OK.MPF"), std::string::npos);
  EXPECT_NE(r.out.find("(1 alarm)"), std::string::npos) << r.out;
}

TEST(CompareCommand, TakesTheRunOptionsDefinitionsIncluded) {
  // The programs use a name from a definition file in another folder (a machine's macro file):
  // compare reads it with --definitions as run does (until 2026-11-30 compare had no such option
  // and the program stopped with 12550). X=_DEPTH_X moves to X12, so both figures agree.
  TempDir dir("drycut_compare_cli_definitions");
  fs::create_directories(dir.path / "defs");
  write_file(dir.path / "defs" / "MACROS.DEF", "DEFINE _DEPTH_X AS 12\nM30\n");
  write_file(dir.path / "A.MPF", "G0 X0 Y0 Z0\nG1 X=_DEPTH_X F1200\nM30\n");
  const fs::path out_json = dir.path / "cmp.json";
  const CliRun r = run_drycut("compare " + quoted(dir.path / "A.MPF") + " " + quoted(dir.path / "A.MPF") +
                              " --definitions " + quoted(dir.path / "defs") + " --json " + quoted(out_json));
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const json cmp = json::parse(read_file(out_json));
  ASSERT_EQ(cmp["programs"].size(), 2u);
  // G0 from the start (0, 0, 100) down 100 mm, then 12 mm of G1.
  EXPECT_NEAR(cmp["programs"][0]["path_length_mm"].get<double>(), 112.0, 1e-9);
}

}  // namespace
