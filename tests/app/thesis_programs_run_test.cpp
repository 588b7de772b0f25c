// The 24 3-D finishing programs of the reference experiment (programs/thesis, the files the
// generator writes: deviation_committed_programs_test) were all milled on the real control, so
// `drycut run` must take every one of them to the end without alarm (a dry run that refuses a
// program the machine ran is the worst error it can make). The only warnings allowed are 10763,
// blocks skipped by the bottleneck detection.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <set>

#include "report_cli_support.hpp"

namespace {

using namespace drycut::report_cli;
using nlohmann::json;

TEST(ThesisProgramRuns, All24FinishingProgramsRunToTheEndWithoutAlarm) {
  const fs::path dir = fs::path(DRYCUT_SOURCE_DIR) / "programs" / "thesis";
  std::set<fs::path> programs;
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.path().extension() == ".MPF" && entry.path().stem().string().find("_2D") == std::string::npos)
      programs.insert(entry.path());
  ASSERT_EQ(programs.size(), 24u);
  TempDir out("drycut_thesis_runs");
  for (const auto& program : programs) {
    const fs::path report = out.path / (program.stem().string() + ".json");
    const CliRun r = run_drycut("run -q " + quoted(program) + " --json " + quoted(report));
    EXPECT_EQ(r.exit_code, 0) << program.filename();
    const json j = json::parse(read_file(report));
    EXPECT_EQ(j["summary"]["complete"], true) << program.filename();
    EXPECT_TRUE(j["alarms"].empty()) << program.filename() << ": " << j["alarms"].dump();
    for (const auto& w : j["warnings"]) EXPECT_EQ(w["number"], 10763) << program.filename() << ": " << w.dump();
    // Every program mills the three loops: 3 x 136.19 mm of contour at least.
    EXPECT_GT(j["summary"]["path_length_mm"].get<double>(), 3 * 136.19) << program.filename();
  }
}

}  // namespace
