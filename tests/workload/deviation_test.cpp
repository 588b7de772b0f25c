// Deviation of programmed and cut contours from a reference curve, against hand formulas.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "machine/machine_profile.hpp"
#include "workload/deviation_program_run.hpp"
#include "workload/deviation_report.hpp"

namespace drycut::workload {
namespace {

namespace fs = std::filesystem;
constexpr double kPi = std::numbers::pi;

class DeviationTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("drycut_deviation_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  DeviationReport evaluate(const std::string& program, double reference_radius,
                           const std::vector<ControlPoint>& control_points = {}) {
    const fs::path file = dir_ / "TEST.MPF";
    std::ofstream(file) << program;
    const machine::MachineProfile profile = machine::default_profile();
    const SampledProgram sampled = sample_program(file, profile, SampleOptions{});
    EXPECT_FALSE(sampled.program_alarm) << sampled.program_alarm->format();
    const CurveSource circle = polar_curve([reference_radius](double) { return reference_radius; });
    const ReferenceContour reference(circle);
    split_ = split_contour(sampled, reference);
    return evaluate_deviation(split_, reference, control_points);
  }

  fs::path dir_;
  ContourSplit split_;
};

TEST_F(DeviationTest, FullCircleProgramFollowsTheReferenceCircle) {
  const auto r = evaluate("N10 G1 X10 Y0 Z0 F1000\nN20 G2 X10 Y0 I-10 J0\nN30 M30\n", 10.0);
  ASSERT_EQ(r.passes.size(), 1u);
  EXPECT_TRUE(r.passes[0].full_loop);
  EXPECT_EQ(r.contour_elements, 1u);  // the approach from Z100 is not contour
  EXPECT_LT(r.passes[0].programmed.max_mm, 1e-5);
  EXPECT_GT(r.passes[0].programmed.samples, 6000u);  // 62.8 mm every 0.01 mm
}

TEST_F(DeviationTest, InscribedPolygonDeviatesByTheSagitta) {
  for (int n : {6, 12, 40}) {
    std::string program = "N10 G1 X10 Y0 Z0 F1000\n";
    for (int k = 1; k <= n; ++k) {
      char line[96];
      std::snprintf(line, sizeof line, "N%d X%.9f Y%.9f\n", 10 + k, 10 * std::cos(2 * kPi * k / n),
                    10 * std::sin(2 * kPi * k / n));
      program += line;
    }
    program += "M30\n";
    const auto r = evaluate(program, 10.0);
    const double sagitta = 10.0 * (1.0 - std::cos(kPi / n));
    ASSERT_EQ(r.passes.size(), 1u) << n;
    EXPECT_NEAR(r.passes[0].programmed.max_mm, sagitta, 2e-5) << n;
    // Along a chord of half-length c the deviation is r - sqrt(a^2 + x^2) (a = r cos(pi/n)); the
    // mean over the chord is known in closed form.
    const double a = 10.0 * std::cos(kPi / n), c = 10.0 * std::sin(kPi / n);
    const double mean_sqrt = 0.5 * (std::sqrt(a * a + c * c) + a * a / c * std::asinh(c / a));
    EXPECT_NEAR(r.passes[0].programmed.mean_mm, 10.0 - mean_sqrt, 1e-3 * (10.0 - mean_sqrt)) << n;  // sampled mean
  }
}

TEST_F(DeviationTest, ControlPointsMeasureTheXDifferenceAtHeldY) {
  // A circle of radius 10.1 against the reference 10: at height y the contour is at
  // x = -sqrt(10.1^2 - y^2) in the second quadrant, the point at -sqrt(10^2 - y^2).
  std::vector<ControlPoint> points{{Vec2(0, 10), true}};
  double expected_sum = 0.1;  // the held-X point: the difference in Y is 0.1
  for (double deg : {100.5, 115.0, 135.0, 155.0, 172.0}) {
    const Vec2 p(10 * std::cos(deg * kPi / 180), 10 * std::sin(deg * kPi / 180));
    points.push_back({p, false});
    expected_sum += std::sqrt(10.1 * 10.1 - p.y() * p.y()) - std::sqrt(100 - p.y() * p.y());
  }
  const auto r = evaluate("N10 G1 X10.1 Y0 Z0 F1000\nN20 G3 X10.1 Y0 I-10.1 J0\nN30 M30\n", 10.0, points);
  ASSERT_EQ(r.control_points.size(), points.size());
  EXPECT_NEAR(*r.control_points[0].programmed_mm, 0.1, 1e-6);
  EXPECT_NEAR(*r.control_points[1].programmed_mm,
              -(std::sqrt(10.1 * 10.1 - points[1].nominal.y() * points[1].nominal.y()) -
                std::sqrt(100 - points[1].nominal.y() * points[1].nominal.y())),
              1e-5);  // the arc is judged as a polyline of 0.01 mm chords
  ASSERT_TRUE(r.programmed_mae.mae_mm);
  EXPECT_NEAR(*r.programmed_mae.mae_mm, expected_sum / 6.0, 1e-5);
  EXPECT_EQ(r.programmed_mae.without_crossing, 0u);
  EXPECT_FALSE(r.tool_cut_mae);  // no compensation: the cut is not judged
  EXPECT_NEAR(r.passes[0].programmed.max_mm, 0.1, 1e-6);
  EXPECT_NEAR(r.passes[0].programmed.mean_mm, 0.1, 1e-6);
}

TEST_F(DeviationTest, PointsWithoutCrossingAreCountedNotDropped) {
  // Circle r = 10.1: the held line y = 10.2 passes over it; y = 8 meets it at
  // x = -sqrt(10.1^2 - 64) from the point (-6, 8).
  const auto r = evaluate("N10 G1 X10.1 Y0 Z0 F1000\nN20 G3 X10.1 Y0 I-10.1 J0\nN30 M30\n", 10.0,
                          {{Vec2(0, 10.2), false}, {Vec2(-6, 8), false}});
  ASSERT_EQ(r.control_points.size(), 2u);
  EXPECT_FALSE(r.control_points[0].programmed_mm);
  EXPECT_EQ(r.programmed_mae.points, 2u);
  EXPECT_EQ(r.programmed_mae.measured, 1u);
  EXPECT_EQ(r.programmed_mae.without_crossing, 1u);
  const double expected = -std::sqrt(10.1 * 10.1 - 64) + 6;
  ASSERT_TRUE(r.programmed_mae.mae_mm);
  EXPECT_NEAR(*r.programmed_mae.mae_mm, std::abs(expected), 1e-5);
  const std::string table = format_table(r);
  EXPECT_NE(table.find("over 1 of 2 points, 1 without crossing within 5 mm"), std::string::npos) << table;
  EXPECT_NE(table.find("none"), std::string::npos) << table;
  const auto j = to_json(r);
  EXPECT_EQ(j["control_point_summary"]["programmed"]["without_crossing"].get<int>(), 1);
  EXPECT_FALSE(j["control_points"][0]["programmed_crossing"].get<bool>());
  EXPECT_TRUE(j["control_points"][0]["tool_cut_crossing"].is_null());
}

TEST_F(DeviationTest, CompensatedCircleCutsTheProgrammedContour) {
  // G42 on a CCW circle puts the tool outside; the envelope of a 2 mm tool is the circle again.
  const auto r = evaluate(
      "N10 T=\"FR_4\"\nN20 M6\nN30 G1 X15 Y0 Z0 F1000\nN40 G42 G1 X10 Y0\nN50 G3 X10 Y0 I-10 J0\n"
      "N60 G40 G1 X15 Y0\nN70 M30\n",
      10.0, {{Vec2(-10 * std::sin(0.3), 10 * std::cos(0.3)), false}});
  EXPECT_DOUBLE_EQ(r.tool_radius_mm, 2.0);
  ASSERT_FALSE(r.passes.empty());
  ASSERT_TRUE(r.all.tool_cut);
  EXPECT_LT(r.all.tool_cut->max_mm, 1e-4);
  ASSERT_TRUE(r.control_points[0].tool_cut_mm);
  EXPECT_NEAR(*r.control_points[0].tool_cut_mm, 0.0, 1e-4);
}

TEST_F(DeviationTest, ToolCutShowsMaterialLeftWhenTheToolPathIsOffsetOutward) {
  // A tool-centre circle of radius 12.1 with no compensation is not judged as a tool cut (no
  // radius requested); with G42 on a programmed radius 10.1 the cut is 0.1 mm outside.
  const auto r = evaluate(
      "N10 T=\"FR_4\"\nN20 M6\nN30 G1 X15 Y0 Z0 F1000\nN40 G42 G1 X10.1 Y0\nN50 G3 X10.1 Y0 I-10.1 J0\n"
      "N60 G40 G1 X15 Y0\nN70 M30\n",
      10.0);
  ASSERT_TRUE(r.all.tool_cut);
  EXPECT_NEAR(r.all.tool_cut->mean_mm, 0.1, 1e-4);
  EXPECT_NEAR(r.all.tool_cut->max_signed_mm, 0.1, 1e-4);  // > 0: material left
}

TEST(ReferenceContour, NearestDistanceOfACircleIsRadialDistance) {
  const ReferenceContour circle(polar_curve([](double) { return 5.0; }));
  EXPECT_NEAR(circle.length(), 2 * kPi * 5, 1e-6);
  for (double a : {0.1, 1.0, 2.5, 4.0}) {
    const auto hit = circle.nearest(Vec2(7 * std::cos(a), 7 * std::sin(a)));
    EXPECT_NEAR(hit.distance, 2.0, 1e-6);
    EXPECT_NEAR(hit.u, a / (2 * kPi), 1e-5);  // ties within the chord error of the polyline
  }
  EXPECT_NEAR(circle.nearest(Vec2(0, 0)).distance, 5.0, 1e-6);
  EXPECT_NEAR(circle.nearest(Vec2(100, 0)).distance, 95.0, 1e-6);  // far outside the grid
}

TEST(PolylineIndex, MatchesBruteForce) {
  std::vector<Vec2> points;
  for (int i = 0; i < 500; ++i) points.emplace_back(std::cos(i * 0.37) * i * 0.05, std::sin(i * 0.91) * 3);
  PolylineIndex index;
  index.add_polyline(points, false);
  index.build();
  for (int q = 0; q < 200; ++q) {
    const Vec2 p(std::sin(q * 1.3) * 30, std::cos(q * 0.7) * 6);
    double brute = 1e300;
    for (size_t i = 0; i + 1 < points.size(); ++i) {
      const Vec2 d = points[i + 1] - points[i];
      const double f = std::clamp((p - points[i]).dot(d) / d.squaredNorm(), 0.0, 1.0);
      brute = std::min(brute, (p - points[i] - f * d).norm());
    }
    EXPECT_NEAR(index.nearest(p).distance, brute, 1e-12);
  }
}

TEST(ControlPoints, ThesisPointsMatchTheExperimentsTable) {
  const auto points = thesis_control_points(polar_curve(thesis_radius));
  ASSERT_EQ(points.size(), 11u);
  EXPECT_TRUE(points[0].hold_x);
  EXPECT_NEAR(points[1].nominal.x(), -3.589, 5e-4);
  EXPECT_NEAR(points[1].nominal.y(), 19.366, 5e-4);
  EXPECT_NEAR(points[4].nominal.x(), -10.512, 5e-4);
  EXPECT_NEAR(points[9].nominal.y(), 2.863, 5e-4);
}

}  // namespace
}  // namespace drycut::workload
