// The `drycut deviation` and `drycut sweep` command-line contract: table, JSON keys, exit codes.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <sys/wait.h>

#include "cli_support.hpp"

namespace {

namespace fs = std::filesystem;

int run(const std::string& args, std::string& out) {
  const drycut::testing::CliRun r = drycut::testing::run_shell(drycut::testing::drycut_command(args) + " 2>/dev/null");
  out += r.out;
  return r.exit_code;
}

class DeviationCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("drycut_deviation_cli_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(DeviationCommand, CircleAgainstPolarReferenceWritesJson) {
  std::ofstream(dir_ / "C.MPF") << "N10 G1 X10 Y0 Z0 F1000\nN20 G3 X10 Y0 I-10 J0\nN30 M30\n";
  std::ofstream(dir_ / "cp.csv") << "x,y,hold\n0,10,x\n-6,8\n";
  std::string out;
  const std::string args = "deviation '" + (dir_ / "C.MPF").string() + "' --polar 10 --control-points '" +
                           (dir_ / "cp.csv").string() + "' --json '" + (dir_ / "d.json").string() + "'";
  ASSERT_EQ(run(args, out), 0) << out;
  EXPECT_NE(out.find("loop 1"), std::string::npos) << out;
  std::ifstream in(dir_ / "d.json");
  const auto j = nlohmann::json::parse(in);
  EXPECT_LT(j["all_passes"]["programmed"]["max_mm"].get<double>(), 1e-5);
  EXPECT_LT(j["control_point_mae_mm"].get<double>(), 1e-5);
  EXPECT_EQ(j["control_points"].size(), 2u);
  EXPECT_EQ(j["held_line_range_mm"].get<double>(), 5.0);
  EXPECT_EQ(j["control_point_summary"]["programmed"]["measured"].get<int>(), 2);
  EXPECT_NE(out.find("over 2 of 2 points, 0 without crossing within 5 mm"), std::string::npos) << out;
}

TEST_F(DeviationCommand, ReadsTheSameDefinitionsAsRun) {
  // CAM posts write CYCLE832(tol,_FINISH,1): _FINISH comes from drycut's CYCLE_MACROS.DEF, and a
  // machine's own definition folder (--definitions) may define it again; deviation must read
  // both as `run` does (before, it stopped at the CYCLE832 line with 12550 and measured nothing).
  std::ofstream(dir_ / "F.MPF") << "N10 G17 G90 G54 T1 D1 M6\nN20 G0 X10 Y0 Z5\nN30 G1 Z0 F2000\n"
                                   "N40 CYCLE832(0.01,_FINISH,1)\nN50 G3 X10 Y0 I-10 J0\nN60 G0 Z50\nN70 M30\n";
  fs::create_directories(dir_ / "defs");
  std::ofstream(dir_ / "defs" / "MYMACROS.DEF") << "DEFINE _OFF AS 0\nDEFINE _FINISH AS 1\nM17\n";
  for (const std::string& extra : {std::string(), " --definitions '" + (dir_ / "defs").string() + "'"}) {
    std::string out;
    ASSERT_EQ(run("deviation '" + (dir_ / "F.MPF").string() + "' --polar 10" + extra, out), 0) << extra << out;
    EXPECT_NE(out.find("loop 1"), std::string::npos) << extra << out;
  }
}

TEST_F(DeviationCommand, HeldLineRangeDecidesWhatCountsAsACrossing) {
  // Circle r = 10 against the reference r = 10.5 (--polar 10.5): the point (-6, 9.5) holds Y;
  // the circle meets y = 9.5 at x = -sqrt(100 - 90.25) = -3.1225, 2.8775 mm away.
  std::ofstream(dir_ / "C.MPF") << "N10 G1 X10 Y0 Z0 F1000\nN20 G3 X10 Y0 I-10 J0\nN30 M30\n";
  std::ofstream(dir_ / "cp.csv") << "-6,9.5\n";
  const std::string base = "deviation '" + (dir_ / "C.MPF").string() + "' --polar 10.5 --capture 1 --control-points '" +
                           (dir_ / "cp.csv").string() + "'";
  std::string near, far;
  ASSERT_EQ(run(base + " --held-line-range 2", near), 0) << near;
  EXPECT_NE(near.find("over 0 of 1 points, 1 without crossing within 2 mm"), std::string::npos) << near;
  ASSERT_EQ(run(base + " --held-line-range 3 --json '" + (dir_ / "d.json").string() + "'", far), 0) << far;
  std::ifstream in(dir_ / "d.json");
  const auto j = nlohmann::json::parse(in);
  EXPECT_NEAR(j["control_points"][0]["programmed_difference_mm"].get<double>(), 6 - std::sqrt(100 - 90.25), 1e-5);
}

TEST_F(DeviationCommand, ProgrammedPointsShowWhereASplineLeavesItsPoints) {
  // G64 lines: the path is the polyline. ASPLINE through the same zigzag: through every knot,
  // off the polyline between them.
  const std::string zigzag = "X10 Y5\nX20 Y0\nX30 Y5\nX40 Y0\nM30\n";
  std::ofstream(dir_ / "L.MPF") << "G0 X0 Y0 Z0\nG64 G1 F1000\n" << zigzag;
  std::ofstream(dir_ / "A.MPF") << "G0 X0 Y0 Z0\nG1 F1000\nASPLINE\n" << zigzag;
  std::string lines, spline;
  ASSERT_EQ(run("deviation '" + (dir_ / "L.MPF").string() + "' --programmed-points", lines), 0) << lines;
  EXPECT_NE(lines.find("path -> programmed polyline: max 0.0000 mm"), std::string::npos) << lines;
  EXPECT_NE(lines.find("programmed points -> path:   max 0.0000 mm"), std::string::npos) << lines;
  ASSERT_EQ(run("deviation '" + (dir_ / "A.MPF").string() + "' --programmed-points", spline), 0) << spline;
  EXPECT_EQ(spline.find("path -> programmed polyline: max 0.0000 mm"), std::string::npos) << spline;
  EXPECT_NE(spline.find("programmed points -> path:   max 0.0000 mm"), std::string::npos) << spline;
  std::string refused;
  EXPECT_EQ(run("deviation '" + (dir_ / "A.MPF").string() + "' --programmed-points --polar 10", refused), 2);
}

TEST_F(DeviationCommand, MissingProgramIsUsageErrorAndBadExpressionAnAlarm) {
  std::string out;
  EXPECT_EQ(run("deviation '" + (dir_ / "NONE.MPF").string() + "'", out), 2);
  std::ofstream(dir_ / "C.MPF") << "N10 G1 X10 Y0 Z0 F1000\nN30 M30\n";
  EXPECT_EQ(run("deviation '" + (dir_ / "C.MPF").string() + "' --polar '10+'", out), 1);
}

TEST_F(DeviationCommand, SweepFindsThePolygonCountOfACircle) {
  std::string out;
  const std::string json = (dir_ / "s.json").string();
  ASSERT_EQ(run("sweep --polar 10 --tolerance 0.1 --methods linear --json '" + json + "'", out), 0) << out;
  std::ifstream in(json);
  const auto j = nlohmann::json::parse(in);
  // n = ceil(pi / acos(1 - 0.1/10)) = 23
  EXPECT_EQ(j["methods"][0]["knots"].get<int>(), 23);
  EXPECT_GT(j["methods"][0]["time_after_m0_s"].get<double>(), 0.0);
}

}  // namespace

namespace {

// `--programmed-points`: the planned path against the program's own points. A circle R20 in 0.5 mm
// chords under COMPCAD (MD33100 0.1 mm per axis in the default profile) strays from the chords,
// but by less than the tolerance band (per axis 0.1 mm: at most 0.1*sqrt(2) in XY); without the
// compressor the planned path is the programmed one.
TEST_F(DeviationCommand, ProgrammedMeasuresTheCompressedPathAgainstTheProgram) {
  for (const char* mode : {"COMPOF", "COMPCAD"}) {
    std::ofstream p(dir_ / (std::string(mode) + ".MPF"));
    p << "G0 X20 Y0 Z0\nG64 " << mode << " F3000\n";
    for (int i = 1; i <= 252; ++i)
      p << "G1 X" << 20 * std::cos(i * 2 * M_PI / 252) << " Y" << 20 * std::sin(i * 2 * M_PI / 252) << "\n";
    p << "M30\n";
    p.close();
    std::string out;
    const fs::path json = dir_ / (std::string(mode) + ".json");
    ASSERT_EQ(run("deviation '" + (dir_ / (std::string(mode) + ".MPF")).string() + "' --programmed-points --json '" +
                      json.string() + "'",
                  out),
              0)
        << out;
    const auto j = nlohmann::json::parse(std::ifstream(json));
    const double path = j["path_to_polyline"]["max_mm"].get<double>(), points = j["points_to_path"]["max_mm"].get<double>();
    EXPECT_GT(j["path_to_polyline"]["count"].get<int>(), 1000);
    EXPECT_EQ(j["points_to_path"]["count"].get<int>(), 253);  // the start position and the 252 end points
    if (std::string(mode) == "COMPOF") {
      EXPECT_LT(path, 1e-9);
      EXPECT_LT(points, 1e-9);
    } else {
      EXPECT_GT(path, 1e-6);  // the compressed path does leave the chords
      EXPECT_LE(path, 0.1 * std::sqrt(2.0));
      EXPECT_LE(points, 0.1 * std::sqrt(2.0));
    }
  }
}

}  // namespace
