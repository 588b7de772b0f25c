#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "workload/curve_source.hpp"
#include "workload/knot_distribution.hpp"

namespace drycut::workload {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

TEST(CurveSource, ThesisContourArcLengthMatchesThesis) {
  // EXPERIMENT.md §1: 136.1895 mm.
  const CurveSource c = polar_curve(thesis_radius);
  ArcLengthTable table(c, c.t_begin, c.t_end, 8192);
  EXPECT_NEAR(table.total(), 136.1895, 5e-4);
}

TEST(CurveSource, CircleArcLengthAndInverse) {
  const CurveSource c = polar_curve([](double) { return 10.0; });
  ArcLengthTable table(c, 0.0, 2 * std::numbers::pi);
  EXPECT_NEAR(table.total(), 20 * std::numbers::pi, 1e-9);
  EXPECT_NEAR(table.length_at(1.0), 10.0, 1e-9);
  EXPECT_NEAR(table.parameter_at(25.0), 2.5, 1e-9);
}

TEST(KnotDistribution, PolarStepsGiveTheThesisCounts) {
  const CurveSource c = polar_curve(thesis_radius);
  EXPECT_EQ(parameter_step_knots(c, 1 * kDeg).size(), 360u);
  EXPECT_EQ(parameter_step_knots(c, 5 * kDeg).size(), 72u);
  const auto k15 = parameter_step_knots(c, 15 * kDeg);
  ASSERT_EQ(k15.size(), 24u);
  // The listing: X22.000 Y0.000, then X21.330 Y1.866 for 5°.
  EXPECT_NEAR(k15[0].point.x(), 22.0, 1e-12);
  const auto k5 = parameter_step_knots(c, 5 * kDeg);
  EXPECT_NEAR(k5[1].point.x(), 21.330, 5e-4);
  EXPECT_NEAR(k5[1].point.y(), 1.866, 5e-4);
}

TEST(KnotDistribution, EqualArcPerQuadrantSpacingMatchesTheExperiment) {
  const CurveSource c = polar_curve(thesis_radius);
  struct Case { int n; size_t distinct; double arc; };
  // Arc per quadrant = 136.1895 / 4 over n-1 gaps.
  for (Case k : {Case{90, 356, 136.1895 / 4 / 89}, Case{45, 176, 136.1895 / 4 / 44}, Case{15, 56, 136.1895 / 4 / 14}}) {
    const auto knots = equal_arc_per_quadrant_knots(c, k.n);
    ASSERT_EQ(knots.size(), k.distinct);
    // Quadrant ends are knots.
    EXPECT_NEAR(knots[0].t, 0.0, 1e-12);
    EXPECT_NEAR(knots[static_cast<size_t>(k.n - 1)].t, std::numbers::pi / 2, 1e-9);
    // Each gap has the same arc length along the true curve.
    ArcLengthTable table(c, c.t_begin, c.t_end, 8192);
    for (size_t i = 1; i < knots.size(); ++i)
      EXPECT_NEAR(table.length_at(knots[i].t) - table.length_at(knots[i - 1].t), k.arc, 2e-4) << i;
  }
}

TEST(KnotDistribution, ChordErrorKnotsKeepTheSagittaBelowTheTolerance) {
  const CurveSource c = polar_curve(thesis_radius);
  const double tol = 0.01;
  const auto knots = chord_error_knots(c, tol);
  ASSERT_GT(knots.size(), 10u);
  double worst = 0;
  for (size_t i = 0; i < knots.size(); ++i) {
    const double t0 = knots[i].t;
    const double t1 = i + 1 < knots.size() ? knots[i + 1].t : c.t_end;
    const Vec3 a = c.point(t0), b = c.point(t1);
    for (int k = 1; k < 50; ++k) {
      const Vec3 p = c.point(t0 + (t1 - t0) * k / 50.0);
      const Vec3 ab = b - a;
      const double u = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
      worst = std::max(worst, (a + u * ab - p).norm());
    }
  }
  EXPECT_LE(worst, tol * 1.05);
  // And it is not wastefully dense: a uniform spacing meeting the tolerance everywhere needs more.
  EXPECT_LT(knots.size(), 400u);
}

}  // namespace
}  // namespace drycut::workload
