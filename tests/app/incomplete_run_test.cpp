// A run stopped by an alarm says so wherever it prints figures: `run`'s text summary, its JSON
// (summary.complete, summary.stopped_at), the HTML report's banner and `compare`'s table and
// JSON. The program cuts two 10 mm lines and then programs a circle whose end point is not on
// it (line 4: start (10,10), centre (5,10), radius 5; end (0,0) lies sqrt(5^2+10^2) = 11.18 mm
// from the centre), which the control refuses with alarm 14040. The figures then cover the blocks
// before it: the same as those of the program cut off before line 4, ending at (10, 10, 0).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "report_cli_support.hpp"

namespace {

using namespace drycut::report_cli;
using nlohmann::json;

constexpr const char* kStops =
    "N10 G0 X0 Y0 Z0\n"
    "N20 G1 X10 F600\n"
    "N30 G1 Y10\n"
    "N40 G2 X0 Y0 I-5 J0\n"
    "N50 G1 X100\n"
    "N60 M30\n";
constexpr const char* kRunsThrough = "N10 G0 X0 Y0 Z0\nN20 G1 X10 F600\nN30 G1 Y10\nN40 M30\n";

TEST(IncompleteRun, TextSummaryNamesTheCyclesItDidNotTime) {
  // CYCLE802 is accepted without simulation (warning 62900 "... no time counted"): the summary
  // says so before the time, naming it once however often it was called.
  TempDir dir("drycut_untimed_text");
  write_file(dir.path / "UNTIMED.MPF", "G17 G90 G0 Z50\nCYCLE802(1,2,3)\nCYCLE802(1,2,3)\nM30\n");
  const CliRun r = run_drycut("run -q " + quoted(dir.path / "UNTIMED.MPF"));
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("NOT TIMED: CYCLE802 (warning 62900): the time below leaves them out"), std::string::npos)
      << r.out;
  EXPECT_LT(r.out.find("NOT TIMED"), r.out.find("  time  ")) << r.out;
  write_file(dir.path / "TIMED.MPF", kRunsThrough);
  EXPECT_EQ(run_drycut("run -q " + quoted(dir.path / "TIMED.MPF")).out.find("NOT TIMED"), std::string::npos);
}

TEST(IncompleteRun, TextSummarySaysWhereItStopped) {
  TempDir dir("drycut_incomplete_text");
  write_file(dir.path / "STOPS.MPF", kStops);
  const CliRun r = run_drycut("run -q " + quoted(dir.path / "STOPS.MPF"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.out.find("INCOMPLETE: stopped by alarm 14040 at STOPS.MPF:4; the figures cover the blocks before it"),
            std::string::npos)
      << r.out;
  // The note stands before the figures it qualifies.
  EXPECT_LT(r.out.find("INCOMPLETE"), r.out.find("path length")) << r.out;

  write_file(dir.path / "THROUGH.MPF", kRunsThrough);
  const CliRun clean = run_drycut("run -q " + quoted(dir.path / "THROUGH.MPF"));
  EXPECT_EQ(clean.exit_code, 0);
  EXPECT_EQ(clean.out.find("INCOMPLETE"), std::string::npos) << clean.out;
}

TEST(IncompleteRun, CsvAndListingFilesEndWithTheMark) {
  // run --trace, path (CSV) and path --elements of the stopped program keep what they wrote and
  // end with one comment line naming the alarm; the complete program's files have none.
  TempDir dir("drycut_incomplete_csv");
  write_file(dir.path / "STOPS.MPF", kStops);
  write_file(dir.path / "THROUGH.MPF", kRunsThrough);
  const std::string mark = "# INCOMPLETE: stopped by alarm 14040 at STOPS.MPF:4; the figures cover the blocks before it\n";
  for (const char* name : {"STOPS.MPF", "THROUGH.MPF"}) {
    const bool stops = std::string(name) == "STOPS.MPF";
    const auto trace = dir.path / (std::string(name) + ".trace.csv");
    EXPECT_EQ(run_drycut("run -q --trace " + quoted(trace) + " " + quoted(dir.path / name)).exit_code, stops ? 1 : 0);
    const auto csv = dir.path / (std::string(name) + ".path.csv");
    run_drycut("path --csv " + quoted(csv) + " " + quoted(dir.path / name));
    const CliRun listing = run_drycut("path --elements " + quoted(dir.path / name));
    for (const std::string& text : {read_file(trace), read_file(csv), listing.out}) {
      const size_t at = text.rfind("# INCOMPLETE");
      if (!stops) {
        EXPECT_EQ(at, std::string::npos) << text;
        continue;
      }
      ASSERT_NE(at, std::string::npos) << text;
      EXPECT_EQ(text.substr(at), mark);  // the last line
      // The rows of N30, the block before the alarm, are kept.
      EXPECT_TRUE(text.find("STOPS.MPF,3\n") != std::string::npos || text.find("STOPS.MPF:3\n") != std::string::npos)
          << text;
    }
  }
}

TEST(IncompleteRun, JsonSummaryHasCompleteAndStoppedAt) {
  TempDir dir("drycut_incomplete_json");
  write_file(dir.path / "STOPS.MPF", kStops);
  write_file(dir.path / "THROUGH.MPF", kRunsThrough);
  const fs::path stops_json = dir.path / "stops.json", through_json = dir.path / "through.json";
  EXPECT_EQ(run_drycut("run -q " + quoted(dir.path / "STOPS.MPF") + " --json " + quoted(stops_json)).exit_code, 1);
  EXPECT_EQ(run_drycut("run -q " + quoted(dir.path / "THROUGH.MPF") + " --json " + quoted(through_json)).exit_code, 0);

  const json stopped = json::parse(read_file(stops_json))["summary"];
  EXPECT_EQ(stopped["complete"], false);
  ASSERT_TRUE(stopped["stopped_at"].is_object()) << stopped.dump(2);
  EXPECT_EQ(fs::path(stopped["stopped_at"]["file"].get<std::string>()).filename(), "STOPS.MPF");
  EXPECT_EQ(stopped["stopped_at"]["line"], 4);
  EXPECT_EQ(stopped["stopped_at"]["alarm"], 14040);
  EXPECT_NEAR(stopped["end_position_mm"]["x"].get<double>(), 10.0, 1e-9);
  EXPECT_NEAR(stopped["end_position_mm"]["y"].get<double>(), 10.0, 1e-9);
  EXPECT_NEAR(stopped["end_position_mm"]["z"].get<double>(), 0.0, 1e-9);

  // The blocks before the alarm run through on their own: complete, nothing stopped it, and the
  // stopped run's figures are theirs.
  const json through = json::parse(read_file(through_json))["summary"];
  EXPECT_EQ(through["complete"], true);
  EXPECT_TRUE(through["stopped_at"].is_null());
  EXPECT_NEAR(stopped["path_length_mm"].get<double>(), through["path_length_mm"].get<double>(), 1e-9);
  EXPECT_NEAR(stopped["time_s"].get<double>(), through["time_s"].get<double>(), 1e-9);
  EXPECT_NEAR(through["end_position_mm"]["x"].get<double>(), 10.0, 1e-9);
  EXPECT_NEAR(through["end_position_mm"]["y"].get<double>(), 10.0, 1e-9);
}

TEST(IncompleteRun, NoMotionHasNoEndPosition) {
  TempDir dir("drycut_incomplete_nomotion");
  write_file(dir.path / "DWELL.MPF", "G4 F0.5\nM30\n");
  const fs::path out = dir.path / "dwell.json";
  EXPECT_EQ(run_drycut("run -q " + quoted(dir.path / "DWELL.MPF") + " --json " + quoted(out)).exit_code, 0);
  const json s = json::parse(read_file(out))["summary"];
  EXPECT_EQ(s["complete"], true);
  EXPECT_TRUE(s["end_position_mm"].is_null()) << s.dump(2);
}

TEST(IncompleteRun, HtmlReportHasTheBannerAtTheTop) {
  TempDir dir("drycut_incomplete_html");
  write_file(dir.path / "STOPS.MPF", kStops);
  write_file(dir.path / "THROUGH.MPF", kRunsThrough);
  const fs::path stops_html = dir.path / "stops.html", through_html = dir.path / "through.html";
  EXPECT_EQ(run_drycut("report -q " + quoted(dir.path / "STOPS.MPF") + " -o " + quoted(stops_html)).exit_code, 1);
  EXPECT_EQ(run_drycut("report -q " + quoted(dir.path / "THROUGH.MPF") + " -o " + quoted(through_html)).exit_code, 0);

  const std::string html = read_file(stops_html);
  const auto banner = html.find("<p id=\"incomplete\"");
  ASSERT_NE(banner, std::string::npos) << html.substr(0, 2000);
  EXPECT_NE(html.find("stopped by alarm 14040 at STOPS.MPF:4; the figures cover the blocks before it", banner),
            std::string::npos);
  // At the top: before the summary and every plot.
  EXPECT_LT(banner, html.find("<h2>Summary</h2>"));
  EXPECT_LT(banner, html.find("<svg"));
  EXPECT_EQ(read_file(through_html).find("id=\"incomplete\""), std::string::npos);
}

TEST(IncompleteRun, CompareMarksTheStoppedProgram) {
  TempDir dir("drycut_incomplete_compare");
  write_file(dir.path / "STOPS.MPF", kStops);
  write_file(dir.path / "THROUGH.MPF", kRunsThrough);
  const fs::path out_json = dir.path / "cmp.json", out_html = dir.path / "cmp.html";
  const CliRun r = run_drycut("compare -q " + quoted(dir.path / "THROUGH.MPF") + " " + quoted(dir.path / "STOPS.MPF") +
                              " --json " + quoted(out_json) + " --html " + quoted(out_html));
  EXPECT_EQ(r.exit_code, 1);
  // Only the stopped program's line is marked, and the table says what that means.
  const auto stops_line = r.out.find("STOPS.MPF");
  ASSERT_NE(stops_line, std::string::npos) << r.out;
  const std::string line = r.out.substr(stops_line, r.out.find('\n', stops_line) - stops_line);
  EXPECT_NE(line.find("INCOMPLETE, stopped by alarm 14040 at STOPS.MPF:4"), std::string::npos) << r.out;
  const auto through_line = r.out.find("THROUGH.MPF");
  EXPECT_EQ(r.out.substr(through_line, r.out.find('\n', through_line) - through_line).find("INCOMPLETE"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("its figures cover only the blocks before it"), std::string::npos) << r.out;

  const json cmp = json::parse(read_file(out_json));
  EXPECT_EQ(cmp["programs"][0]["complete"], true);
  EXPECT_TRUE(cmp["programs"][0]["stopped_at"].is_null());
  EXPECT_EQ(cmp["programs"][1]["complete"], false);
  EXPECT_EQ(cmp["programs"][1]["stopped_at"]["line"], 4);
  EXPECT_EQ(cmp["programs"][1]["stopped_at"]["alarm"], 14040);

  const std::string html = read_file(out_html);
  EXPECT_NE(html.find("<tr class=\"incomplete\">"), std::string::npos);
  EXPECT_NE(html.find("incomplete, stopped by alarm 14040 at STOPS.MPF:4"), std::string::npos);
  EXPECT_NE(html.find("id=\"incomplete\""), std::string::npos);
}

}  // namespace
