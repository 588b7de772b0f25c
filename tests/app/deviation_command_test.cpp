// The `drycut deviation` and `drycut sweep` command-line contract: table, JSON keys, exit codes.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <unistd.h>

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
