// End to end: the CAM finishing program programs/examples/cam_finishing/MOULD_4711_FINISH.MPF
// (written by gen_cam_finishing.py in the style of a CAM post for the 840D: DEF variables,
// machine-data checks, named tool, CYCLE832, G54 + TRANS/AROT, 13040 short G1 blocks) must pass
// `drycut check` and `drycut run` without an alarm, execute the hand-counted number of blocks and
// traverse the path length computed independently (by the generator from its points, and here
// from the program text).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <regex>
#include <sstream>
#include <string>

#include "cli_support.hpp"

namespace {

namespace fs = std::filesystem;
using drycut::testing::CliRun;

const fs::path kFolder = fs::path(DRYCUT_SOURCE_DIR) / "programs" / "examples" / "cam_finishing";
const fs::path kProgram = kFolder / "MOULD_4711_FINISH.MPF";

// A number from a header comment line "; KEY : value ..." (the generator's figures).
double header_value(const std::string& text, const std::string& key) {
  const std::regex re("; " + key + R"(\s*:\s*([0-9.]+))");
  std::smatch m;
  if (!std::regex_search(text, m, re)) return NAN;
  return std::stod(m[1]);
}

std::string read_all(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

struct Body {
  int blocks = 0;
  double length = 0;  // sum of the straight segments between the markers (workpiece system)
};

// The generated G1 blocks between the markers, read with modal X/Y/Z from the plunge point
// `N56G1Z<z>` (which follows `N52G0X0.Y0.`): rotation and translation keep lengths, so the sum
// in the workpiece system is the sum on the machine.
Body read_body(const std::string& text) {
  Body b;
  std::istringstream in(text);
  std::string line;
  double p[3] = {0, 0, 0};
  bool inside = false;
  static const std::regex plunge(R"(^N56G1Z([-0-9.]+)F)");
  static const std::regex word(R"(([XYZ])(-?[0-9]+\.?[0-9]*))");
  while (std::getline(in, line)) {
    std::smatch m;
    if (std::regex_search(line, m, plunge)) p[2] = std::stod(m[1]);
    if (line.rfind("; --- generated toolpath", 0) == 0) { inside = true; continue; }
    if (line.rfind("; --- end of generated toolpath", 0) == 0) break;
    if (!inside) continue;
    double q[3] = {p[0], p[1], p[2]};
    for (auto it = std::sregex_iterator(line.begin(), line.end(), word); it != std::sregex_iterator(); ++it)
      q[(*it)[1].str()[0] - 'X'] = std::stod((*it)[2]);
    b.length += std::sqrt((q[0] - p[0]) * (q[0] - p[0]) + (q[1] - p[1]) * (q[1] - p[1]) + (q[2] - p[2]) * (q[2] - p[2]));
    for (int k = 0; k < 3; ++k) p[k] = q[k];
    ++b.blocks;
  }
  return b;
}

bool has_alarm(const nlohmann::json& list) {
  for (const auto& a : list)
    if (a["severity"] != "warning") return true;
  return false;
}

TEST(CamFinishingProgram, ChecksAndRunsWithTheHandComputedBlocksAndLength) {
  ASSERT_TRUE(fs::exists(kProgram)) << kProgram;
  const std::string text = read_all(kProgram);
  const Body body = read_body(text);
  const double generated_blocks = header_value(text, "MOTION BLOCKS");
  const double generated_path = header_value(text, "PATH LENGTH");
  const double generated_g1 = header_value(text, "G1 LENGTH");
  ASSERT_EQ(body.blocks, generated_blocks);
  // 81 passes of 160 steps (X 0..80 by 0.5, Y 0..60 by 0.75) plus 80 step-overs, less the first
  // point, which the plunge block reaches: 81 * 161 - 1 = 13040 blocks.
  ASSERT_EQ(body.blocks, 81 * 161 - 1);
  // G1 length = plunge (_ZCLEAR = 5 mm, N56) + the generated blocks, in both computations.
  EXPECT_NEAR(body.length + 5.0, generated_g1, 1e-3);

  // check: blocks executed, counted by hand. drycut counts a block that carries an NC word it
  // acts on (G, M, S, T, D, F, axes, frame, MSG); DEF, assignments, IF/ELSE/ENDIF and call-only
  // lines are not blocks of their own, nor is a line with only unmodelled words.
  //   before the toolpath: G71 (ELSE branch on the metric machine), N30 MSG, N32, N34, N36,
  //     N38, N40, N42 TRANS, N44 AROT, CYCLE832(_TOL,1,1) = CUST_832's G642 SOFT COMPCAD
  //     FFWON DYNFINISH + its M17 + CYCLE832's M17, CYCLE832's CTOL=_TOL,
  //     N48, N50, N52, N54, N56                                                        = 18
  //   the toolpath                                                                     = 13040
  //   after it: N..G0Z, FFWOF COMPOF M5, CYCLE832() = CUST_832's G64 COMPOF DYNNORM + its M17
  //     + CYCLE832's M17, CYCLE832's CTOL=-1 OTOL=-1, TRANS, G0 SUPA, MSG(), M30         = 10
  //   (CTOL= is modelled since corner smoothing, docs/smoothing.md: its lines are blocks)
  const fs::path json = fs::temp_directory_path() / ("drycut_cam_" + std::to_string(::getpid()) + ".json");
  const CliRun check = drycut::testing::run_shell("cd '" + kFolder.string() + "' && " +
                                                  drycut::testing::drycut_command("check MOULD_4711_FINISH.MPF --json") +
                                                  " 2>/dev/null");
  ASSERT_EQ(check.exit_code, 0) << check.out;
  const auto c = nlohmann::json::parse(check.out);
  EXPECT_EQ(c["blocks_executed"].get<int>(), 18 + 13040 + 10);
  EXPECT_FALSE(has_alarm(c["alarms"]));

  const CliRun run = drycut::testing::run_in_folder("run", kProgram, "--tools tools.csv -q --json '" + json.string() + "'");
  ASSERT_EQ(run.exit_code, 0) << run.out;
  const auto j = nlohmann::json::parse(std::ifstream(json));
  fs::remove(json);
  EXPECT_FALSE(has_alarm(j["alarms"]));
  EXPECT_TRUE(j["alarms"].empty());
  EXPECT_TRUE(j["summary"]["complete"].get<bool>());
  // No warning but "not modelled" ones (990002; FFWON/FFWOF no longer warn): the tool is in tools.csv.
  for (const auto& w : j["warnings"]) EXPECT_EQ(w["number"], 990002) << w.dump();

  // Path length: the generator sums every move in machine coordinates from the start (0,0,100)
  // (G0 SUPA Z280, G0 to the frame's X0 Y0, G0 down with the tool length 90, plunge, toolpath,
  // G0 Z50, G0 SUPA Z280). CYCLE832 selects COMPCAD: the toolpath is the compressed curve,
  // within the tolerance of the polyline, so its length is that of the polyline up to a small
  // share (the 0.5 mm blocks of a pass are joined into smooth spans; the corners at the pass
  // ends are kept by COMPCAD and then rounded by G642 within MD33100, each rounding up to about
  // 0.15 mm shorter than the corner it cuts, about 160 of them: docs/smoothing.md).
  const auto& s = j["summary"];
  EXPECT_NEAR(s["path_length_mm"].get<double>(), generated_path, 5e-3 * generated_path);
  EXPECT_LT(s["path_length_mm"].get<double>(), generated_path);
  // Block rows are arrays in the order of "block_columns" (docs/schemas/run.schema.json).
  const auto& columns = j["block_columns"];
  const auto column = [&columns](const char* name) {
    return static_cast<size_t>(std::find(columns.begin(), columns.end(), name) - columns.begin());
  };
  const size_t rapid = column("rapid"), length = column("length_mm"), label = column("label");
  ASSERT_LT(rapid, columns.size());
  ASSERT_LT(length, columns.size());
  double g1 = 0, g0 = 0;
  size_t compressed_blocks = 0;
  for (const auto& row : j["blocks"]) {
    (row[rapid].get<bool>() ? g0 : g1) += row[length].get<double>();
    // A compressor span has two more values; a G642 rounding one more (smoothing_deviation_mm).
    if (row.size() > columns.size() && row[label] != "G642") compressed_blocks += row[columns.size()].get<size_t>();
  }
  // The G642 roundings cut the pass-end corners (about 0.3 % of the G1 length, see above).
  EXPECT_NEAR(g1, generated_g1, 5e-3 * generated_g1);
  EXPECT_LT(g1, generated_g1);
  EXPECT_GT(compressed_blocks, 12000u);  // nearly all of the 13040 toolpath blocks

  // End: the last point X80 Y60 of the workpiece, turned by AROT Z15 and shifted by TRANS X50
  // Y40, at the tool change height: x = 80 cos15 - 60 sin15 + 50 = 111.7449,
  // y = 80 sin15 + 60 cos15 + 40 = 118.6611, z = 280 (SUPA, machine coordinates).
  const double c15 = std::cos(15 * std::numbers::pi / 180), s15 = std::sin(15 * std::numbers::pi / 180);
  EXPECT_NEAR(s["end_position_mm"]["x"].get<double>(), 80 * c15 - 60 * s15 + 50, 1e-6);
  EXPECT_NEAR(s["end_position_mm"]["y"].get<double>(), 80 * s15 + 60 * c15 + 40, 1e-6);
  EXPECT_NEAR(s["end_position_mm"]["z"].get<double>(), 280.0, 1e-6);

  // Time can only be longer than feeding the G1 length at F3000 (F800 for the 5 mm plunge)
  // plus the 4 s tool change of the default profile.
  const double lower = (g1 - 5.0) / 3000.0 * 60.0 + 5.0 / 800.0 * 60.0 + 4.0;
  EXPECT_GT(s["time_s"].get<double>(), lower);
}

}  // namespace
