// `drycut run --span FROM..TO`: the named events in summary.events, the span in summary.span_s
// and in the text summary. The program, on the embedded MCV 1210 (BRISK and G60, the reset
// state: every block starts and ends at rest; 5 m/s^2 per axis), from X0 Y0 Z100:
//   N10 G1 X10 F600   10 mm at 10 mm/s: t = L/v + v/a = 1 + 10/5000 = 1.002 s
//   N20 M0            no time                                  -> after_m0    = 1.002
//   N30 G4 F2         2 s                                      -> after_dwell = 3.002
//   N40 G1 X20        1.002 s
//   N50 SPANSUB       G1 Y10, G1 Y20: 1.002 s each             -> contour_start = 4.004,
//                                                                 contour_end   = 6.008
//   N60 G1 X30        1.002 s                                  -> end           = 7.010
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "report_cli_support.hpp"

namespace {

using namespace drycut::report_cli;
using nlohmann::json;

constexpr const char* kMain = "N10 G1 X10 F600\nN20 M0\nN30 G4 F2\nN40 G1 X20\nN50 SPANSUB\nN60 G1 X30\nN70 M30\n";
constexpr const char* kSub = "N10 G1 Y10\nN20 G1 Y20\nN30 M17\n";

struct SpanProgram {
  TempDir dir{"drycut_run_span"};
  fs::path main = dir.path / "SPAN.MPF";
  SpanProgram() {
    write_file(main, kMain);
    write_file(dir.path / "SPANSUB.SPF", kSub);
  }
};

TEST(RunSpan, JsonHasEveryEventAndTheSpan) {
  SpanProgram p;
  const fs::path out = p.dir.path / "run.json";
  ASSERT_EQ(run_drycut("run -q " + quoted(p.main) + " --span after_m0..contour_end --json " + quoted(out)).exit_code, 0);
  const json s = json::parse(read_file(out))["summary"];
  const json& e = s["events"];
  EXPECT_NEAR(e["start"].get<double>(), 0.0, 1e-12);
  EXPECT_NEAR(e["after_m0"].get<double>(), 1.002, 1e-9);
  EXPECT_NEAR(e["after_dwell"].get<double>(), 3.002, 1e-9);
  EXPECT_NEAR(e["contour_start"].get<double>(), 4.004, 1e-9);
  EXPECT_NEAR(e["contour_end"].get<double>(), 6.008, 1e-9);
  EXPECT_NEAR(e["end"].get<double>(), 7.010, 1e-9);
  EXPECT_EQ(s["span"], "after_m0..contour_end");
  EXPECT_NEAR(s["span_s"].get<double>(), 6.008 - 1.002, 1e-9);
  // The existing keys stay, and agree: end is the total, after_m0 the total minus time_after_m0_s.
  EXPECT_NEAR(s["time_s"].get<double>(), 7.010, 1e-9);
  EXPECT_NEAR(s["time_after_m0_s"].get<double>(), 7.010 - 1.002, 1e-9);
}

TEST(RunSpan, TextSummaryPrintsTheSpan) {
  SpanProgram p;
  const CliRun r = run_drycut("run -q " + quoted(p.main) + " --span after_dwell..contour_end");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("span after_dwell..contour_end"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("3.01 s"), std::string::npos) << r.out;  // 6.008 - 3.002 = 3.006
}

TEST(RunSpan, WithoutSpanTheEventsAreThereAndTheSpanIsNull) {
  SpanProgram p;
  const fs::path out = p.dir.path / "run.json";
  ASSERT_EQ(run_drycut("run -q " + quoted(p.main) + " --json " + quoted(out)).exit_code, 0);
  const json s = json::parse(read_file(out))["summary"];
  EXPECT_NEAR(s["events"]["contour_start"].get<double>(), 4.004, 1e-9);
  EXPECT_TRUE(s["span"].is_null());
  EXPECT_TRUE(s["span_s"].is_null());
}

TEST(RunSpan, AnEventTheRunDoesNotReachHasNoTime) {
  // Without M0 and without a call: after_m0, contour_* are null; after_dwell is the first dwell.
  TempDir dir("drycut_run_span_missing");
  write_file(dir.path / "PLAIN.MPF", "N10 G1 X10 F600\nN20 G4 F1\nN30 M30\n");
  const fs::path out = dir.path / "run.json";
  const CliRun r =
      run_drycut("run -q " + quoted(dir.path / "PLAIN.MPF") + " --span after_m0..end --json " + quoted(out));
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("the run has no after_m0"), std::string::npos) << r.out;
  const json s = json::parse(read_file(out))["summary"];
  EXPECT_TRUE(s["events"]["after_m0"].is_null());
  EXPECT_TRUE(s["events"]["contour_start"].is_null());
  EXPECT_TRUE(s["events"]["contour_end"].is_null());
  EXPECT_NEAR(s["events"]["after_dwell"].get<double>(), 2.002, 1e-9);
  EXPECT_TRUE(s["span_s"].is_null());
}

TEST(RunSpan, UnknownEventIsAUsageError) {
  SpanProgram p;
  for (const char* bad : {"after_m0..finish", "after_m0", "..end"}) {
    const fs::path err = p.dir.path / "stderr.txt";
    const CliRun r = run_drycut("run -q " + quoted(p.main) + " --span " + bad, err.string());
    EXPECT_EQ(r.exit_code, 2) << bad;
    const std::string message = read_file(err);
    EXPECT_NE(message.find("after_dwell"), std::string::npos) << bad << ": " << message;  // lists the events
  }
}

}  // namespace
