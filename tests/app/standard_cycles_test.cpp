// drycut's own standard cycles (programs/cycles, docs/cycles.md) end to end: the conformance
// programs of tests/conformance/cycles*/ hold hand-computed expectations in their header
// (`; expect: ok`, `; expect-warning: N`, `; expect-end: X.. Y.. Z..`, `; expect-time: T tol D`);
// this reads them and checks `drycut check`, `drycut run --json` and `drycut path --elements`.
// (The shared conformance runner takes these programs over once it exists; this keeps the
// cycles' numbers checked until then.) Plus: CYCLE832 means its CUST_832 settings, and
// --no-standard-cycles leaves the cycles out of the search path.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "cli_support.hpp"

namespace {

namespace fs = std::filesystem;
using drycut::testing::CliRun;

struct Expectations {
  bool ok = false;
  std::vector<int> warnings;
  std::map<char, double> end;  // axis -> mm
  bool has_time = false;
  double time_s = 0, time_tol = 0;
};

Expectations read_expectations(const fs::path& file) {
  Expectations e;
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line) && line.rfind(';', 0) == 0) {
    std::istringstream s(line.substr(1));
    std::string key;
    s >> key;
    if (key == "expect:") {
      std::string what;
      s >> what;
      e.ok = what == "ok";
    } else if (key == "expect-warning:") {
      int n = 0;
      if (s >> n) e.warnings.push_back(n);
    } else if (key == "expect-end:") {
      std::string word;
      while (s >> word) e.end[word[0]] = std::stod(word.substr(1));
    } else if (key == "expect-time:") {
      std::string tol;
      e.has_time = static_cast<bool>(s >> e.time_s >> tol >> e.time_tol) && tol == "tol";
    }
  }
  return e;
}

std::vector<fs::path> conformance_programs() {
  std::vector<fs::path> out;
  for (const char* topic : {"cycles", "cycles_override"})
    for (const auto& entry : fs::directory_iterator(fs::path(DRYCUT_TEST_DIR) / "conformance" / topic))
      if (entry.path().extension() == ".mpf") out.push_back(entry.path());
  std::sort(out.begin(), out.end());
  return out;
}

// The end point of the last motion element in `drycut path --elements` output.
bool last_end_point(const std::string& listing, double xyz[3]) {
  static const std::regex re(R"(-> \(([-0-9.]+) ([-0-9.]+) ([-0-9.]+)\))");
  bool found = false;
  for (auto it = std::sregex_iterator(listing.begin(), listing.end(), re); it != std::sregex_iterator(); ++it) {
    for (int k = 0; k < 3; ++k) xyz[k] = std::stod((*it)[k + 1]);
    found = true;
  }
  return found;
}

TEST(StandardCycles, ConformanceProgramsMeetTheirHandComputedExpectations) {
  const auto programs = conformance_programs();
  ASSERT_GE(programs.size(), 8u);
  const fs::path json = fs::temp_directory_path() / ("drycut_cycles_" + std::to_string(::getpid()) + ".json");
  for (const auto& program : programs) {
    SCOPED_TRACE(program.filename().string());
    const Expectations e = read_expectations(program);
    ASSERT_TRUE(e.ok) << "only `expect: ok` programs here";
    EXPECT_EQ(drycut::testing::run_in_folder("check", program, "").exit_code, 0);

    const CliRun run = drycut::testing::run_in_folder("run", program, "-q --json '" + json.string() + "'");
    ASSERT_EQ(run.exit_code, 0) << run.out;
    const auto j = nlohmann::json::parse(std::ifstream(json));
    for (int n : e.warnings) {
      const auto& w = j["warnings"];
      EXPECT_TRUE(std::any_of(w.begin(), w.end(), [n](const auto& x) { return x["number"] == n; }))
          << "warning " << n << " missing: " << run.out;
    }
    if (e.has_time) {
      EXPECT_NEAR(j["summary"]["time_s"].get<double>(), e.time_s, e.time_tol);
    }

    if (!e.end.empty()) {
      const CliRun path = drycut::testing::run_in_folder("path", program, "--elements");
      double xyz[3];
      ASSERT_TRUE(last_end_point(path.out, xyz)) << path.out;
      const std::string axes = "XYZ";
      for (const auto& [axis, value] : e.end) EXPECT_NEAR(xyz[axes.find(axis)], value, 1e-3) << axis;
    }
  }
  fs::remove(json);
}

class CycleRuns : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("drycut_cycles_cli_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  double time_of(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
    const fs::path json = dir_ / (name + ".json");
    const CliRun r = drycut::testing::run_in_folder("run", dir_ / name, "-q --json '" + json.string() + "'");
    EXPECT_EQ(r.exit_code, 0) << r.out;
    return nlohmann::json::parse(std::ifstream(json))["summary"]["time_s"].get<double>();
  }
  fs::path dir_;
};

// CYCLE832 (docs/cycles.md) programs CTOL and calls CUST_832, whose default for finishing is
// G642 SOFT COMPCAD FFWON DYNFINISH: a corner-rich contour takes exactly as long either way.
TEST_F(CycleRuns, Cycle832TakesAsLongAsItsSettingsWrittenOut) {
  const std::string contour = "G1 X10 Y0.2\nX20 Y-0.2\nX30 Y0.3\nX40 Y0\nY10\nX0\nM30\n";
  const double by_cycle = time_of("BY_CYCLE.MPF", "G17 G90 G94 F3000\nG0 Z0\nCYCLE832(0.01,1)\n" + contour);
  const double written =
      time_of("WRITTEN.MPF", "G17 G90 G94 F3000\nG0 Z0\nCTOL=0.01 OTOL=-1\nG642 SOFT COMPCAD FFWON DYNFINISH\n" + contour);
  const double brisk = time_of("BRISK.MPF", "G17 G90 G94 F3000\nG0 Z0\n" + contour);
  EXPECT_DOUBLE_EQ(by_cycle, written);
  EXPECT_NE(by_cycle, brisk);  // the settings do shape the time
}

// A machine builder's CUST_832 beside the program replaces drycut's default: here finishing
// selects exact stop and BRISK, so the cycle's run takes as long as the plain G60 BRISK one.
TEST_F(CycleRuns, OwnCust832ReplacesTheDefault) {
  std::ofstream(dir_ / "CUST_832.SPF") << "PROC CUST_832(INT _MODE)\nG60 BRISK\nM17\n";
  const std::string contour = "G1 X10 Y0.2\nX20 Y-0.2\nX30 Y0.3\nM30\n";
  const double by_cycle = time_of("OWN.MPF", "G17 G90 G94 F3000\nG0 Z0\nG64 SOFT\nCYCLE832(0.01,1)\n" + contour);
  const double exact = time_of("EXACT.MPF", "G17 G90 G94 F3000\nG0 Z0\nG60 BRISK\n" + contour);
  EXPECT_DOUBLE_EQ(by_cycle, exact);
}

// A CAM post's header and finishing settings say nothing the user must act on: drycut's own
// CYCLE832 and CUST_832 (OTOL=, FFWON) and the post's TRAFOOF, FIFOCTRL, OVR=100 and neutral
// ACC/VELOLIM/JERKLIM run without a single warning (docs/controller-state.md, "Feeds" and
// "Dynamics").
TEST_F(CycleRuns, CamHeaderRunsWithoutWarnings) {
  std::ofstream(dir_ / "HEADER.MPF") << "G40 G17 G710 G94 G90\nTRAFOOF\nFIFOCTRL\nOVR=100\n"
                                        "ACC[X]=100 VELOLIM[X]=100 JERKLIM[X]=100\nCYCLE832(0.01,_FINISH,1)\n"
                                        "G0 X0 Y0 Z50\nG1 X10 F2000\nCYCLE832()\nM30\n";
  const CliRun r = drycut::testing::run_in_folder("run", dir_ / "HEADER.MPF", "-q");
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_EQ(r.out.find("WARNING"), std::string::npos) << r.out;
}

TEST_F(CycleRuns, NoStandardCyclesLeavesThemOutOfTheSearchPath) {
  std::ofstream(dir_ / "MAIN.MPF") << "G0 Z50\nF100\nCYCLE81(50,0,2,-10)\nM30\n";
  EXPECT_EQ(drycut::testing::run_in_folder("check", dir_ / "MAIN.MPF", "").exit_code, 0);
  const CliRun r = drycut::testing::run_in_folder("check", dir_ / "MAIN.MPF", "--no-standard-cycles");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.out.find("ALARM 14011"), std::string::npos) << r.out;
}

}  // namespace
