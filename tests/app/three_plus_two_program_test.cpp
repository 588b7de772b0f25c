// End to end: the 3+2 programs programs/examples/three_plus_two/BRACKET_3P2_{MM,INCH}.MPF
// (style of a 5-axis post: CYCLE800 to an inclined face B-30 and to the front face A90, CYCLE83
// at three holes per face, a G41 pocket wall per face; the inch variant programs G700) must run
// end to end, and pass through hand-computed points in machine coordinates.
//
// How drycut defines the points (docs/controller-state.md): machine = frame chain applied to the
// programmed point; G54 of the default profile is zero, and CYCLE800 in axis-by-axis mode 57
// (bits 1-0, 3-2, 5-4: X, then Y, then Z) builds TRANS (_X0, _Y0, _Z0) * AROT X=_A * AROT Y=_B * AROT Z=_C. The
// tools in tools.csv have length 0 (see the program folder's README: drycut would add a length
// along machine Z, not along the swivelled tool axis), so no length term enters.
//
//   face 1: CYCLE800(..,57, 0,0,Z0, 0,-30,0, ..): m = (0, 0, Z0) + Ry(-30) p,
//           Ry(-30) (x, y, z) = (cos30 x - sin30 z, y, sin30 x + cos30 z)
//                             = (0.8660254 x - 0.5 z, y, 0.5 x + 0.8660254 z)
//   face 2: CYCLE800(..,57, 0,0,0, 90,0,0, ..): m = Rx(90) p = (x, -z, y)
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <unistd.h>

#include <Eigen/Core>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "cli_support.hpp"

namespace {

namespace fs = std::filesystem;
using drycut::testing::CliRun;
using Eigen::Vector3d;

const fs::path kFolder = fs::path(DRYCUT_SOURCE_DIR) / "programs" / "examples" / "three_plus_two";
constexpr double kMmPerInch = 25.4;

// Face 1 (swivel B-30 about the reference point (0, 0, z0)); all in mm.
Vector3d face1(double x, double y, double z, double z0) {
  const double c = std::sqrt(3.0) / 2, s = 0.5;
  return {c * x - s * z, y, s * x + c * z + z0};
}
// Face 2 (swivel A90 about the zero point).
Vector3d face2(double x, double y, double z) { return {x, -z, y}; }

std::vector<Vector3d> element_end_points(const std::string& listing) {
  static const std::regex re(R"(-> \(([-0-9.]+) ([-0-9.]+) ([-0-9.]+)\))");
  std::vector<Vector3d> out;
  for (auto it = std::sregex_iterator(listing.begin(), listing.end(), re); it != std::sregex_iterator(); ++it)
    out.emplace_back(std::stod((*it)[1]), std::stod((*it)[2]), std::stod((*it)[3]));
  return out;
}

// Samples of `drycut path --tool-centre --csv`: s_mm,x,y,z,element,file,line.
std::vector<Vector3d> tool_centre_samples(const fs::path& csv) {
  std::vector<Vector3d> out;
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    std::istringstream s(line);
    std::string field[4];
    for (auto& f : field) std::getline(s, f, ',');
    out.emplace_back(std::stod(field[1]), std::stod(field[2]), std::stod(field[3]));
  }
  return out;
}

double nearest(const std::vector<Vector3d>& points, const Vector3d& p) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& q : points) best = std::min(best, (q - p).norm());
  return best;
}

struct Expected {
  std::string program;
  std::vector<Vector3d> points;        // programmed points: element end points (listing, 0.001 mm)
  std::vector<Vector3d> tool_centres;  // G41 tool-centre corners
  Vector3d end;                        // summary.end_position_mm
  double max_feed_mm_min;
};

void check_program(const Expected& e) {
  SCOPED_TRACE(e.program);
  const fs::path program = kFolder / e.program;
  const CliRun check = drycut::testing::run_in_folder("check", program, "");
  EXPECT_EQ(check.exit_code, 0) << check.out;
  EXPECT_EQ(check.out.find("ALARM"), std::string::npos) << check.out;

  const std::string tag = std::to_string(::getpid()) + "_" + program.stem().string();
  const fs::path json = fs::temp_directory_path() / ("drycut_3p2_" + tag + ".json");
  const CliRun run = drycut::testing::run_in_folder("run", program, "--tools tools.csv -q --json '" + json.string() + "'");
  ASSERT_EQ(run.exit_code, 0) << run.out;
  const auto j = nlohmann::json::parse(std::ifstream(json));
  fs::remove(json);
  EXPECT_TRUE(j["alarms"].empty()) << j["alarms"].dump();
  EXPECT_TRUE(j["summary"]["complete"].get<bool>());
  // The only warnings: TCOABS in CYCLE800 (no swivel kinematics), 990002, and the swivel motion
  // not timed (the default profile has no rotary axes in its swivel data), 62900.
  for (const auto& w : j["warnings"]) EXPECT_TRUE(w["number"] == 990002 || w["number"] == 62900) << w.dump();
  const auto& end = j["summary"]["end_position_mm"];
  EXPECT_NEAR(end["x"].get<double>(), e.end.x(), 1e-6);
  EXPECT_NEAR(end["y"].get<double>(), e.end.y(), 1e-6);
  EXPECT_NEAR(end["z"].get<double>(), e.end.z(), 1e-6);
  EXPECT_NEAR(j["summary"]["max_feed_mm_min"].get<double>(), e.max_feed_mm_min, 1e-6);

  const CliRun listing = drycut::testing::run_in_folder("path", program, "--elements --tools tools.csv");
  ASSERT_EQ(listing.exit_code, 0) << listing.out;
  const auto ends = element_end_points(listing.out);
  // Printed to 0.001 mm: each axis within 0.0005, the distance within 0.00087.
  for (const auto& p : e.points) EXPECT_LT(nearest(ends, p), 9e-4) << "no element ends at " << p.transpose();

  const fs::path csv = fs::temp_directory_path() / ("drycut_3p2_" + tag + ".csv");
  const CliRun centre = drycut::testing::run_in_folder(
      "path", program, "--tools tools.csv --tool-centre --step 0.02 --csv '" + csv.string() + "'");
  ASSERT_EQ(centre.exit_code, 0) << centre.out;
  const auto samples = tool_centre_samples(csv);
  fs::remove(csv);
  // Samples every 0.02 mm: the nearest lies within half a step of a corner.
  for (const auto& p : e.tool_centres) EXPECT_LT(nearest(samples, p), 0.011) << "tool centre misses " << p.transpose();
}

TEST(ThreePlusTwoProgram, MetricRunsThroughTheHandComputedPoints) {
  Expected e;
  e.program = "BRACKET_3P2_MM.MPF";
  e.points = {
      face1(20, 20, 50, 30),   // N90 G0 X20 Y20 Z50: (17.3205 - 25, 20, 10 + 43.3013 + 30) = (-7.6795, 20, 83.3013)
      face1(20, 20, -12, 30),  // hole 1 bottom: (17.3205 + 6, 20, 10 - 10.3923 + 30) = (23.3205, 20, 29.6077)
      face1(40, 40, -12, 30),  // hole 3 bottom: (34.6410 + 6, 40, 20 - 10.3923 + 30) = (40.6410, 40, 39.6077)
      face1(50, 20, -3, 30),   // pocket corner X50 Y20 Z-3: (43.3013 + 1.5, 20, 25 - 2.5981 + 30) = (44.8013, 20, 52.4019)
      face2(20, 15, -10),      // face 2 hole 1 bottom: (20, 10, 15)
      face2(80, 40, -10),      // face 2 hole 3 bottom: (80, 10, 40)
      face2(90, 10, -3),       // face 2 pocket corner X90 Y10: (90, 3, 10)
  };
  // G41 counter-clockwise inside the pocket, radius 5: the tool centre at an inside corner is
  // the corner moved 5 mm into the pocket along both walls.
  e.tool_centres = {
      face1(45, 25, -3, 30),  // (38.9711 + 1.5, 25, 22.5 - 2.5981 + 30) = (40.4711, 25, 49.9019)
      face2(85, 15, -3),      // (85, 3, 15)
  };
  e.end = {75, -50, 280};  // face 2 G0 Z50 at X75 Y20 = (75, -50, 20), then G0 SUPA Z280
  e.max_feed_mm_min = 900;
  check_program(e);
}

TEST(ThreePlusTwoProgram, InchRunsThroughTheHandComputedPoints) {
  // G700: every length of the program is inch (x 25.4), F in in/min; the tool radius is mm.
  const double in = kMmPerInch;
  Expected e;
  e.program = "BRACKET_3P2_INCH.MPF";
  e.points = {
      // N90 G0 X.8 Y.8 Z2.: (0.69282 - 1.0, 0.8, 0.4 + 1.73205 + 1.2) in = (-7.8024, 20.32, 84.6341) mm
      face1(.8 * in, .8 * in, 2 * in, 1.2 * in),
      // hole 1 bottom Z-.5: (0.69282 + 0.25, 0.8, 0.4 - 0.43301 + 1.2) in = (23.9476, 20.32, 29.6416) mm
      face1(.8 * in, .8 * in, -.5 * in, 1.2 * in),
      // pocket corner X2. Y.8 Z-.12: (1.73205 + 0.06, 0.8, 1.0 - 0.10392 + 1.2) in = (45.5181, 20.32, 53.2404) mm
      face1(2 * in, .8 * in, -.12 * in, 1.2 * in),
      face2(2 * in, .8 * in, -.4 * in),    // face 2 hole 2 bottom: (2.0, 0.4, 0.8) in = (50.8, 10.16, 20.32) mm
      face2(3.6 * in, .4 * in, -.12 * in), // face 2 pocket corner: (3.6, 0.12, 0.4) in = (91.44, 3.048, 10.16) mm
  };
  e.tool_centres = {
      // (2.0 in - 5, 0.8 in + 5, -0.12 in) = (45.8, 25.32, -3.048) mm -> (41.1880, 25.32, 50.7403)
      face1(2 * in - 5, .8 * in + 5, -.12 * in, 1.2 * in),
      // (3.6 in - 5, 0.4 in + 5, -3.048) = (86.44, 15.16, -3.048) mm -> (86.44, 3.048, 15.16)
      face2(3.6 * in - 5, .4 * in + 5, -.12 * in),
  };
  e.end = {3 * in, -2 * in, 11 * in};  // face 2 G0 Z2. at X3. Y.8, then G0 SUPA Z11.: (76.2, -50.8, 279.4)
  e.max_feed_mm_min = 36 * in;          // F36. in/min = 914.4 mm/min
  check_program(e);
}

}  // namespace
