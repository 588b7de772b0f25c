// `drycut profile import` and `drycut profile show` end to end: the MD text file of the machine
// tests → a profile file and its source map; the table names each value's datum and file:line;
// the imported profile drives a run whose time is computed by hand.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "cli_support.hpp"

namespace drycut::testing {
namespace {

namespace fs = std::filesystem;

const std::string kMdFile = DRYCUT_TEST_DIR "/machine/data/mill_4axis_md.txt";

fs::path fresh_folder() {
  const fs::path dir = fs::temp_directory_path() / ("drycut_profile_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

TEST(ProfileCommand, ImportWritesProfileAndSourcesAndReportsMissing) {
  const fs::path dir = fresh_folder();
  const CliRun r =
      run_shell(drycut_command("profile import '" + kMdFile + "' -o '" + (dir / "mill.json").string() + "'"));
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_TRUE(fs::exists(dir / "mill.json"));
  EXPECT_TRUE(fs::exists(dir / "mill.sources.json"));
  EXPECT_NE(r.out.find("missing (drycut's default taken):"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("MD20602 CURV_EFFECT_ON_PATH_ACCEL"), std::string::npos) << r.out;

  const CliRun show = run_shell(drycut_command("profile show '" + (dir / "mill.json").string() + "'"));
  ASSERT_EQ(show.exit_code, 0) << show.out;
  // One row: key, value, datum, file:line of the machine data.
  EXPECT_NE(show.out.find("axes.C.max_velocity_deg_min"), std::string::npos) << show.out;
  EXPECT_NE(show.out.find("MD32000 MAX_AX_VELO"), std::string::npos) << show.out;
  EXPECT_NE(show.out.find("mill_4axis_md.txt:77"), std::string::npos) << show.out;
  EXPECT_NE(show.out.find("9000.0"), std::string::npos) << show.out;  // 25 rev/min = 9000 deg/min
  EXPECT_NE(show.out.find("missing from the machine data at import"), std::string::npos) << show.out;

  // The imported machine runs a program: G0 X300 under BRISK (reset table) from X0 on X
  // (30000 mm/min = 500 mm/s, 2.5 m/s²): accelerate 0.2 s over 50 mm, cruise 200 mm in 0.4 s,
  // brake 0.2 s: 0.8 s.
  std::ofstream(dir / "G0.MPF") << "G0 X300\nM30\n";
  const CliRun run = run_in_folder("run --json t.json -q", dir / "G0.MPF", "--machine mill.json");
  ASSERT_EQ(run.exit_code, 0) << run.out;
  std::ifstream json(dir / "t.json");
  std::string text((std::istreambuf_iterator<char>(json)), std::istreambuf_iterator<char>());
  const size_t at = text.find("\"time_s\":");
  ASSERT_NE(at, std::string::npos) << text.substr(0, 400);
  EXPECT_NEAR(std::stod(text.substr(at + 9)), 0.8, 0.02);
  fs::remove_all(dir);
}

TEST(ProfileCommand, ShowTheEmbeddedProfileAndErrors) {
  const CliRun show = run_shell(drycut_command("profile show"));
  ASSERT_EQ(show.exit_code, 0) << show.out;
  EXPECT_NE(show.out.find("axes.X.max_velocity_mm_min"), std::string::npos) << show.out;
  EXPECT_NE(show.out.find("embedded mcv1210.json"), std::string::npos) << show.out;
  EXPECT_EQ(run_shell(drycut_command("profile import /nonexistent/md.txt -o /tmp/x.json 2>/dev/null")).exit_code, 2);
  EXPECT_EQ(run_shell(drycut_command("profile show /nonexistent.json 2>/dev/null")).exit_code, 2);
}

TEST(ProfileCommand, UnknownResetCodeIsAProfileErrorNotAnInternalOne) {
  // A reset code drycut does not know (reset_gcodes, the MD20150 analogue) is the profile's
  // fault: a usage error naming the file and the code, exit 2, not "internal error".
  const fs::path dir = fresh_folder();
  std::ifstream in(DRYCUT_SOURCE_DIR "/src/machine/profiles/mcv1210.json");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const size_t at = text.find("\"reset_gcodes\": [");
  ASSERT_NE(at, std::string::npos);
  text.insert(at + std::string("\"reset_gcodes\": [").size(), "\"G999\", ");
  std::ofstream(dir / "bad.json") << text;
  std::ofstream(dir / "P.MPF") << "G1 X1 F100\nM30\n";
  const CliRun r = run_shell(drycut_command("run -q --machine '" + (dir / "bad.json").string() + "' '" +
                                            (dir / "P.MPF").string() + "' 2>&1"));
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.out.find("bad.json: reset_gcodes: 'G999' is not a modal code drycut knows"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("internal error"), std::string::npos) << r.out;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace drycut::testing
