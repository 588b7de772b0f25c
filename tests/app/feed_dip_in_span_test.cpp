// A feed dip inside a compressed span is reported at the programmed block where the lowest
// velocity is, not at the span's first block (docs/compressor.md, "Where a dip lies").
// The program, under G64 SOFT COMPCAD with F10000 (166.7 mm/s): blocks of 0.5 mm along X to
// X20, a quarter circle of radius 2 around (20, 2) in 16 blocks of 5.6 deg (lines 43..58, no
// corner for SD42470), then 0.5 mm blocks along Y. The quarter circle is symmetric about its
// middle, and so is the compressed span over it: the lowest velocity (the curvature and jerk
// limit of the bend) lies at the arc's middle, the end of its 8th block, line 50. Until
// 2026-11-29 the dip named the first block of the span it fell in (line 45).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "report_cli_support.hpp"

namespace {

using namespace drycut::report_cli;

std::string quarter_circle_program() {
  std::string t = "G17 G90 G94 G64 SOFT COMPCAD\nG0 X0 Y0 Z0 G9\nG1 X0.5 F10000\n";
  char buf[64];
  for (int k = 2; k <= 40; ++k) {  // lines 4..42: X1 .. X20
    std::snprintf(buf, sizeof buf, "X%.4f\n", 0.5 * k);
    t += buf;
  }
  for (int k = 1; k <= 16; ++k) {  // lines 43..58
    const double a = -0.5 * std::numbers::pi + k * 0.5 * std::numbers::pi / 16;
    std::snprintf(buf, sizeof buf, "X%.4f Y%.4f\n", 20 + 2 * std::cos(a), 2 + 2 * std::sin(a));
    t += buf;
  }
  for (int k = 1; k <= 40; ++k) {
    std::snprintf(buf, sizeof buf, "Y%.4f\n", 2 + 0.5 * k);
    t += buf;
  }
  return t + "M30\n";
}

TEST(FeedDipInSpan, NamesTheBlockOfTheLowestVelocity) {
  TempDir dir{"drycut_dip_span"};
  const fs::path program = dir.path / "BEND.MPF", out = dir.path / "run.json";
  write_file(program, quarter_circle_program());
  ASSERT_EQ(run_drycut("run -q " + quoted(program) + " --json " + quoted(out)).exit_code, 0);
  const auto j = nlohmann::json::parse(read_file(out));
  int spans = 0;  // rows: file, line, label, ...
  for (const auto& row : j["blocks"]) spans += row[2] == "COMPCAD";
  ASSERT_GT(spans, 0) << "the run is compressed";
  ASSERT_EQ(j["dips"].size(), 1u) << j["dips"].dump();
  EXPECT_EQ(j["dips"][0]["line"], 50) << j["dips"][0].dump();
  EXPECT_LT(j["dips"][0]["v_min_mm_min"].get<double>(), 10000.0 * 0.8);
}

TEST(FeedDipStretch, APassHeldDownByTheShortBlockRuleSaysSo) {
  // 400 chords of 0.1 mm at F3000 (50 mm/s) under G64, no compressor, entered at a right angle:
  // a block must last one IPO cycle (4 ms), so 0.1 mm blocks run at most 25 mm/s (times the
  // profile's short-block factor), below 80 % of F along the whole pass. The one dip is lowest
  // at the corner and bound by the short-block rule over most of its length; the summary says
  // so on a line of its own. Until 2026-11-30 it read as a single corner.
  TempDir dir{"drycut_dip_stretch"};
  const fs::path program = dir.path / "PASS.MPF", out = dir.path / "run.json";
  std::string t = "G17 G90 G94 G64\nG0 X20 Y0 Z0\nG1 X20.1 F3000\n";
  char buf[64];
  for (int k = 1; k <= 400; ++k) {
    std::snprintf(buf, sizeof buf, "X20.1 Y%.1f\n", 0.1 * k);
    t += buf;
  }
  write_file(program, t + "M30\n");
  const auto run = run_drycut("run " + quoted(program) + " --json " + quoted(out));
  ASSERT_EQ(run.exit_code, 0);
  const auto j = nlohmann::json::parse(read_file(out));
  ASSERT_EQ(j["dips"].size(), 1u) << j["dips"].dump();
  const auto& d = j["dips"][0];
  EXPECT_EQ(d["limit"], "corner") << d.dump();
  EXPECT_EQ(d["main_limit"], "short_block") << d.dump();
  EXPECT_GT(d["length_mm"].get<double>(), 39.0) << d.dump();  // nearly the whole 40.1 mm
  EXPECT_NE(run.out.find("mostly short_block"), std::string::npos) << run.out;
}

}  // namespace
