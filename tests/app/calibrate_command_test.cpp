// `drycut calibrate` end to end: times measured (planned) with a profile whose path jerk is known,
// calibrated from the embedded profile, must give that jerk back; fields the runs do not depend
// on are refused with exit 2; the output does not change from one run to the next.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli_support.hpp"

namespace drycut::testing {
namespace {

namespace fs = std::filesystem;

// A closed polygon of G1 blocks under G64 SOFT (the corner and jerk limits act), in a folder.
struct Workspace {
  fs::path dir = fs::temp_directory_path() / ("drycut-calibrate-" + std::to_string(::getpid()));
  Workspace() {
    fs::create_directories(dir);
    write_polygon("P12.MPF", 12, 10, 3000);
    write_polygon("P30.MPF", 30, 20, 2000);
    write_polygon("P7.MPF", 7, 6, 4000);
  }
  ~Workspace() { fs::remove_all(dir); }

  void write_polygon(const std::string& name, int sides, double r, int feed) const {
    std::ofstream out(dir / name);
    out << "G90 G17 G64 SOFT\nG1 X" << r << " Y0 F" << feed << "\n";
    for (int k = 1; k <= sides; ++k) {
      const double a = 2 * M_PI * k / sides;
      out << "X" << r * std::cos(a) << " Y" << r * std::sin(a) << "\n";
    }
    out << "M30\n";
  }

  // The embedded profile with the path jerk set to `jerk` m/s³.
  fs::path profile_with_path_jerk(double jerk) const {
    std::ifstream in(DRYCUT_SOURCE_DIR "/src/machine/profiles/mcv1210.json");
    nlohmann::json p = nlohmann::json::parse(in);
    p["path"]["max_path_jerk_m_s3"] = jerk;
    const fs::path f = dir / "truth.json";
    std::ofstream(f) << p.dump(2);
    return f;
  }

  double planned_time(const std::string& program, const fs::path& profile) const {
    const CliRun r = run_shell("cd '" + dir.string() + "' && " +
                               drycut_command("run " + program + " -q --machine '" + profile.string() +
                                              "' --json out.json") + " 2>&1");
    EXPECT_EQ(r.exit_code, 0) << r.out;
    std::ifstream in(dir / "out.json");
    return nlohmann::json::parse(in)["summary"]["time_s"].get<double>();
  }

  fs::path measurements(double jerk) const {
    const fs::path truth = profile_with_path_jerk(jerk);
    nlohmann::json runs = nlohmann::json::array();
    for (const char* p : {"P12.MPF", "P30.MPF", "P7.MPF"}) runs.push_back({{"program", p}, {"time", planned_time(p, truth)}});
    const fs::path f = dir / "measured.json";
    std::ofstream(f) << nlohmann::json{{"runs", runs}}.dump(2);
    return f;
  }

  CliRun calibrate(const fs::path& measured, const std::string& args) const {
    return run_shell(drycut_command("calibrate '" + measured.string() + "' " + args + " -o '" +
                                    (dir / "fitted.json").string() + "' --jobs 2") + " 2>&1");
  }
};

TEST(CalibrateCommand, RecoversTheKnownPathJerk) {
  Workspace w;
  const fs::path measured = w.measurements(12.0);  // the embedded profile has 20 m/s³
  const CliRun r = w.calibrate(measured, "--fit path_jerk");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  std::ifstream in(w.dir / "fitted.json");
  const nlohmann::json fitted = nlohmann::json::parse(in);
  EXPECT_NEAR(fitted["path"]["max_path_jerk_m_s3"].get<double>(), 12.0, 0.12) << r.out;
  EXPECT_NE(r.out.find("leave-one-out"), std::string::npos) << r.out;
}

TEST(CalibrateCommand, RefusesAFieldTheRunsDoNotDependOn) {
  Workspace w;
  const fs::path measured = w.measurements(12.0);
  const CliRun r = w.calibrate(measured, "--fit tool_change_time");  // no M6 in the programs
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.out.find("cannot identify tool_change_time"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(w.dir / "fitted.json"));
}

TEST(CalibrateCommand, UnknownFieldIsAUsageError) {
  Workspace w;
  const CliRun r = w.calibrate(w.measurements(12.0), "--fit colour");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("unknown field 'colour'"), std::string::npos) << r.out;
}

TEST(CalibrateCommand, SameInputSameOutput) {
  Workspace w;
  const fs::path measured = w.measurements(30.0);
  const CliRun a = w.calibrate(measured, "--fit path_jerk,ovl_factor --no-loo");
  const CliRun b = w.calibrate(measured, "--fit path_jerk,ovl_factor --no-loo");
  ASSERT_EQ(a.exit_code, 0) << a.out;
  EXPECT_EQ(a.out, b.out);
}

// The re-planned recording gives what the whole pipeline gives: calibrate's start column (the
// base profile) equals `drycut run --span` of the same program to the printed digit.
TEST(CalibrateCommand, ReplayMatchesTheFullRun) {
  Workspace w;
  const fs::path thesis = fs::path(DRYCUT_SOURCE_DIR) / "programs" / "thesis";
  nlohmann::json runs = nlohmann::json::array();
  for (const char* p : {"EKVI_LIN_15.MPF", "EKVI_C_15.MPF"})
    runs.push_back({{"program", fs::relative(thesis / p, w.dir).string()}, {"time", 20.0}});
  const fs::path measured = w.dir / "thesis.json";
  std::ofstream(measured) << nlohmann::json{{"span", "after_dwell..contour_end"}, {"runs", runs}}.dump(2);
  const CliRun fit = w.calibrate(measured, "--fit path_jerk --no-loo");
  ASSERT_EQ(fit.exit_code, 0) << fit.out;
  for (const char* p : {"EKVI_LIN_15.MPF", "EKVI_C_15.MPF"}) {
    const CliRun run = run_shell("cd '" + thesis.string() + "' && " +
                                 drycut_command(std::string("run ") + p + " -q --span after_dwell..contour_end") + " 2>&1");
    const auto at = run.out.find("span after_dwell..contour_end");
    ASSERT_NE(at, std::string::npos) << run.out;
    double span = 0;
    std::istringstream(run.out.substr(at + 30)) >> span;
    const auto row = fit.out.find(std::string("/") + p);
    ASSERT_NE(row, std::string::npos) << fit.out;
    std::istringstream line(fit.out.substr(fit.out.rfind('\n', row) + 1));
    std::string name;
    double measured_s = 0, start_s = 0;
    line >> name >> measured_s >> start_s;
    EXPECT_GT(span, 15.0) << run.out;  // parsed: the span is about 20 s
    EXPECT_NEAR(start_s, span, 0.005) << p << "\n" << fit.out << run.out;
  }
}

}  // namespace
}  // namespace drycut::testing
