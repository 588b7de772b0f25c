// The path against the program's own points (`deviation --programmed-points`), against
// hand-computed distances: a semicircle over its chord, a rounded corner, rapids breaking runs,
// and whole programs (G1: zero; splines through or near their knots).
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "machine/machine_profile.hpp"
#include "workload/programmed_point_deviation.hpp"

namespace drycut::workload {
namespace {

namespace fs = std::filesystem;
constexpr double kPi = std::numbers::pi;

SampledElement line(const Vec3& a, const Vec3& b, bool rapid = false, int n = 1000) {
  SampledElement e;
  for (int i = 0; i <= n; ++i) e.points.push_back(a + (b - a) * (static_cast<double>(i) / n));
  e.rapid = rapid;
  return e;
}

SampledElement arc(const Vec3& centre, double radius, double from, double to, int n = 20000) {
  SampledElement e;
  for (int i = 0; i <= n; ++i) {
    const double a = from + (to - from) * i / n;
    e.points.push_back(centre + radius * Vec3(std::cos(a), std::sin(a), 0));
  }
  return e;
}

TEST(PolylineDistance, PointToSegmentsByHand) {
  const PolylineDistance d({{Vec3(0, 0, 0), Vec3(10, 0, 0), Vec3(10, 10, 0)}});
  EXPECT_NEAR(d.distance(Vec3(5, 3, 4)), 5.0, 1e-12);    // above the first segment
  EXPECT_NEAR(d.distance(Vec3(12, 5, 0)), 2.0, 1e-12);   // beside the second
  EXPECT_NEAR(d.distance(Vec3(-3, -4, 0)), 5.0, 1e-12);  // beyond the first vertex
  EXPECT_TRUE(std::isinf(PolylineDistance({}).distance(Vec3::Zero())));
}

TEST(PolylineDistance, ChunksFarFromThePointAreSkippedNotMissed) {
  // 2000 collinear points on the X axis (63 chunks) and a second polyline far away: from
  // (x, 3, 4) the distance is 5 anywhere along the axis, and sqrt(25 + 4) off its end.
  std::vector<Vec3> axis;
  for (int i = 0; i < 2000; ++i) axis.emplace_back(0.1 * i, 0, 0);
  const PolylineDistance d({axis, {Vec3(500, 500, 0), Vec3(600, 500, 0)}});
  for (double x : {0.0, 57.33, 199.9, 120.0, 3.0}) EXPECT_NEAR(d.distance(Vec3(x, 3, 4)), 5.0, 1e-12) << x;
  EXPECT_NEAR(d.distance(Vec3(201.9, 3, 4)), std::sqrt(29.0), 1e-9);
  EXPECT_NEAR(d.distance(Vec3(550, 497, 0)), 3.0, 1e-12);
}

TEST(ProgrammedPointDeviation, SemicircleOverItsChord) {
  // Programmed (0,0) -> (10,0), the path the upper semicircle about (5,0): the path is up to
  // 5 mm off the chord, 5 sin(a) on average over a = 0..pi: 10/pi; it passes through both points.
  const std::vector<ProgrammedPoint> points{{Vec3(0, 0, 0), true, {}, {}}, {Vec3(10, 0, 0), false, {}, {}}};
  const auto d = programmed_point_deviation(points, {arc(Vec3(5, 0, 0), 5.0, kPi, 0.0)});
  EXPECT_EQ(d.programmed_points, 2u);
  EXPECT_EQ(d.polylines, 1u);
  EXPECT_NEAR(d.path_to_polyline.max_mm, 5.0, 1e-6);
  EXPECT_NEAR(d.path_to_polyline.mean_mm, 10.0 / kPi, 1e-3);
  EXPECT_NEAR(d.points_to_path.max_mm, 0.0, 1e-12);
}

TEST(ProgrammedPointDeviation, RoundedCornerMissesThePoint) {
  // Programmed (0,0) -> (10,0) -> (10,10); the path rounds the corner with a quarter circle of
  // radius 2 about (8,2): it misses the corner by 2 sqrt(2) - 2 and bulges 2 - sqrt(2) from the
  // polyline at the arc's middle.
  const std::vector<ProgrammedPoint> points{
      {Vec3(0, 0, 0), true, {}, {}}, {Vec3(10, 0, 0), false, {}, {}}, {Vec3(10, 10, 0), false, {}, {}}};
  const auto d = programmed_point_deviation(
      points, {line(Vec3(0, 0, 0), Vec3(8, 0, 0)), arc(Vec3(8, 2, 0), 2.0, -kPi / 2, 0.0),
               line(Vec3(10, 2, 0), Vec3(10, 10, 0))});
  EXPECT_NEAR(d.points_to_path.max_mm, 2 * std::sqrt(2.0) - 2, 1e-6);
  EXPECT_NEAR(d.points_to_path.mean_mm, (2 * std::sqrt(2.0) - 2) / 3, 1e-6);
  EXPECT_NEAR(d.path_to_polyline.max_mm, 2 - std::sqrt(2.0), 1e-6);
}

TEST(ProgrammedPointDeviation, RapidsStartNewPolylines) {
  // Start Z100, rapid to Z5, feed down and along X, rapid over to (50,50,5), feed down. The
  // rapid's path is not judged, and the two runs are separate polylines: the line from (10,0,0)
  // to (50,50,5) is no programmed contour.
  const std::vector<ProgrammedPoint> points{{Vec3(0, 0, 100), true, {}, {}}, {Vec3(0, 0, 5), true, {}, {}},  {Vec3(0, 0, 0), false, {}, {}},
                                            {Vec3(10, 0, 0), false, {}, {}}, {Vec3(50, 50, 5), true, {}, {}}, {Vec3(50, 50, 0), false, {}, {}}};
  const auto d = programmed_point_deviation(
      points, {line(Vec3(0, 0, 100), Vec3(0, 0, 5), true), line(Vec3(0, 0, 5), Vec3(0, 0, 0)),
               line(Vec3(0, 0, 0), Vec3(10, 0, 0)), line(Vec3(10, 0, 0), Vec3(50, 50, 5), true),
               line(Vec3(50, 50, 5), Vec3(50, 50, 0))});
  EXPECT_EQ(d.polylines, 2u);
  EXPECT_EQ(d.programmed_points, 5u);
  EXPECT_NEAR(d.path_to_polyline.max_mm, 0.0, 1e-12);
  EXPECT_NEAR(d.points_to_path.max_mm, 0.0, 1e-12);
  EXPECT_EQ(d.path_to_polyline.count, 3u * 1001u);
}

class ProgrammedPointProgram : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("drycut_points_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::pair<SampledProgram, ProgrammedPointDeviation> run(const std::string& program) {
    std::ofstream(dir_ / "P.MPF") << program;
    SampleOptions options;
    options.tool_centre = false;
    SampledProgram s = sample_program(dir_ / "P.MPF", machine::default_profile(), options);
    EXPECT_FALSE(s.program_alarm);
    const auto d = programmed_point_deviation(s.programmed_points, s.programmed);
    return {std::move(s), d};
  }
  fs::path dir_;
};

constexpr const char* kZigzag = "X10 Y5\nX20 Y0\nX30 Y5\nX40 Y0\nX50 Y5\nG1 X60 Y0\nM30\n";

TEST_F(ProgrammedPointProgram, LinesFollowTheirPointsExactly) {
  const auto [s, d] = run(std::string("G0 X0 Y0 Z5\nG1 Z0 F1000\nG64\n") + kZigzag);
  // Start (0,0,100) in G54 = machine zero with the default profile; the points as programmed.
  ASSERT_EQ(s.programmed_points.size(), 9u);
  EXPECT_TRUE(s.programmed_points[1].rapid);
  EXPECT_FALSE(s.programmed_points[3].rapid);
  EXPECT_NEAR((s.programmed_points[3].position - Vec3(10, 5, 0)).norm(), 0.0, 1e-12);
  EXPECT_EQ(d.polylines, 1u);
  EXPECT_LT(d.path_to_polyline.max_mm, 1e-9);
  EXPECT_LT(d.points_to_path.max_mm, 1e-9);
}

TEST_F(ProgrammedPointProgram, InterpolatingSplinePassesItsKnotsAndBulgesBetween) {
  const auto [s, d] = run(std::string("G0 X0 Y0 Z0\nG1 X0 F1000\nASPLINE\n") + kZigzag);
  EXPECT_LT(d.points_to_path.max_mm, 1e-6);  // A spline passes through every knot
  EXPECT_GT(d.path_to_polyline.max_mm, 0.05);  // and leaves the zigzag between them
}

TEST_F(ProgrammedPointProgram, ArcsAreMeasuredAlongTheirCircleNotTheirChord) {
  // A quarter circle r = 10 and a full circle: the path is the programmed contour itself, so
  // both figures are 0 (up to the sampling: the contour's points are the arc's samples at 0.01 mm,
  // their chords 0.01^2 / (8 r) = 1.25e-6 mm inside the circle). Against the chords it was
  // the sagitta 10 (1 - cos 45 deg) = 2.93 mm and the diameter 20 mm (a full circle's chord is a point).
  const auto [s, d] =
      run("G0 X10 Y0 Z0\nG1 X10 F1000\nG3 X0 Y10 CR=10\nG1 X-5\nG2 X-5 Y10 I0 J-10\nG1 Y20\nM30\n");
  EXPECT_EQ(d.programmed_points, 5u);  // the arcs' points densify the contour, they are not counted
  EXPECT_LT(d.path_to_polyline.max_mm, 1e-5);
  EXPECT_LT(d.points_to_path.max_mm, 1e-9);
}

TEST_F(ProgrammedPointProgram, BSplineMissesItsControlPoints) {
  const auto [s, d] = run(std::string("G0 X0 Y0 Z0\nG1 X0 F1000\nBSPLINE\n") + kZigzag);
  EXPECT_GT(d.points_to_path.max_mm, 0.5);  // the B spline does not pass through its points
}

}  // namespace
}  // namespace drycut::workload
