// Offsets that loop (a bend tighter than the tool radius on the compensation side) and the
// distance invariant of the tool-centre path on the thesis contour.
//
// Reference for the loop: the offset of the parabola y = x^2 / 2 by r = 2 on its concave side
// passes the axis twice, at x = +-sqrt(4 a^2 r^2 - 1) / (2a) = +-sqrt(3) of the base, in the point
// (0, a x^2 + 1/(2a)) = (0, 2.5). The cut path goes straight through that point.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "compensation_test_curves.hpp"
#include "cutter_compensation_test_support.hpp"
#include "interp/cutter_compensation.hpp"
#include "polyline_distance.hpp"

namespace drycut::interp {
namespace {

using geometry::Vec3;
using test::Comp;
using test::line;

using test::StageRun;

PathElement parabola_span(double x0, double x1, const Comp& comp, uint32_t block_line) {
  return test::motion(std::make_shared<test::ParabolaCurve>(0.5, x0, x1), ElementKind::SplineSpan, comp, block_line);
}

// Smallest distance from p to the parabola y = x^2/2, x in [-4, 4] (dense sampling + refinement).
double distance_to_parabola(const Vec3& p) {
  double best = std::numeric_limits<double>::infinity();
  double best_x = 0.0;
  for (int i = 0; i <= 8000; ++i) {
    const double x = -4.0 + 8.0 * i / 8000;
    const double d = std::hypot(p.x() - x, p.y() - 0.5 * x * x);
    if (d < best) best = d, best_x = x;
  }
  for (double h = 1e-3; h > 1e-12; h *= 0.5)
    for (double x : {best_x - h, best_x + h}) {
      if (x < -4.0 || x > 4.0) continue;
      const double d = std::hypot(p.x() - x, p.y() - 0.5 * x * x);
      if (d < best) best = d, best_x = x;
    }
  return best;
}

void expect_tool_path_at_radius(const std::vector<PathElement>& contour_elements, double radius) {
  for (const auto& e : contour_elements)
    for (int i = 0; i <= 20; ++i) {
      const Vec3 p = e.curve->at(e.curve->length() * i / 20).position;
      EXPECT_NEAR(distance_to_parabola(p), radius, 1e-3) << "line " << e.source.line << " at " << p.transpose();
    }
}

TEST(CutterCompensationLoop, LoopAcrossBlocksIsCutAndTheMiddleBlockSkipped) {
  StageRun run;
  Comp comp{.side = CompensationSide::Left};
  run.feed({line({-10, 8, 0}, {-4, 8, 0}, comp, 1), parabola_span(-4, -1, comp, 2), parabola_span(-1, 1, comp, 3),
            parabola_span(1, 4, comp, 4), line({4, 8, 0}, {10, 8, 0}, comp.off(), 5)});
  const auto& out = run.sink.elements;
  ASSERT_EQ(out.size(), 4u);
  EXPECT_EQ(out[1].source.line, 2u);
  EXPECT_EQ(out[1].kind, ElementKind::SplineSpan);
  EXPECT_LT((out[1].curve->end() - Vec3(0, 2.5, 0)).norm(), 1e-6);
  EXPECT_EQ(out[2].source.line, 4u);
  EXPECT_LT((out[2].curve->start() - Vec3(0, 2.5, 0)).norm(), 1e-6);
  test::expect_continuous(out);
  expect_tool_path_at_radius({out[1], out[2]}, 2.0);
  ASSERT_EQ(run.diagnostics.items().size(), 1u);
  EXPECT_EQ(run.diagnostics.items()[0].number, 10763);
  EXPECT_EQ(run.diagnostics.items()[0].where.line, 3u);
}

TEST(CutterCompensationLoop, LoopInsideOneBlockIsCutWithoutWarning) {
  StageRun run;
  Comp comp{.side = CompensationSide::Left};
  run.feed({line({-10, 8, 0}, {-4, 8, 0}, comp, 1), parabola_span(-4, 4, comp, 2),
            line({4, 8, 0}, {10, 8, 0}, comp.off(), 3)});
  const auto& out = run.sink.elements;
  ASSERT_EQ(out.size(), 4u);
  EXPECT_EQ(out[1].source.line, 2u);
  EXPECT_EQ(out[2].source.line, 2u);
  EXPECT_LT((out[1].curve->end() - Vec3(0, 2.5, 0)).norm(), 1e-6);
  test::expect_continuous(out);
  expect_tool_path_at_radius({out[1], out[2]}, 2.0);
  EXPECT_TRUE(run.diagnostics.items().empty());
}

TEST(CutterCompensationLoop, GentleBendOnTheOtherSideIsNotCut) {
  StageRun run;
  Comp comp{.side = CompensationSide::Right};
  run.feed({line({-10, 8, 0}, {-4, 8, 0}, comp, 1), parabola_span(-4, -1, comp, 2), parabola_span(-1, 1, comp, 3),
            parabola_span(1, 4, comp, 4)});
  const auto& out = run.sink.elements;
  ASSERT_EQ(out.size(), 4u);
  expect_tool_path_at_radius({out[1], out[2], out[3]}, 2.0);
  EXPECT_TRUE(run.diagnostics.items().empty());
}

// The thesis contour r(theta) = 18 + 4 cos 6theta cos 2theta as 0.05 mm chords, milled outside
// with G42 counter-clockwise: every tool-centre sample lies 2 mm from the polyline.
TEST(CutterCompensationLoop, ThesisContourToolPathIsAtToolRadiusEverywhere) {
  auto polar = [](double t) {
    const double r = 18 + 4 * std::cos(6 * t) * std::cos(2 * t);
    return Vec3(r * std::cos(t), r * std::sin(t), -6);
  };
  std::vector<Vec3> points{polar(0.0)};
  const int fine = 200000;
  for (int i = 1; i <= fine; ++i) {
    const Vec3 p = polar(2 * std::numbers::pi * i / fine);
    if ((p - points.back()).norm() >= 0.05 || i == fine) points.push_back(p);
  }
  points.back() = points.front();
  Comp comp{.side = CompensationSide::Right};
  std::vector<PathElement> elements{line({30, 0, -6}, points[0], comp, 1)};
  for (size_t i = 1; i < points.size(); ++i) elements.push_back(line(points[i - 1], points[i], comp, uint32_t(i + 1)));
  elements.push_back(line(points.back(), {30, 0, -6}, comp.off(), uint32_t(points.size() + 1)));
  StageRun run;
  run.feed(elements);
  const auto& out = run.sink.elements;
  ASSERT_GT(out.size(), points.size());
  test::expect_continuous(out);
  EXPECT_TRUE(run.diagnostics.items().empty());
  std::vector<Eigen::Vector2d> poly;
  for (const Vec3& p : points) poly.emplace_back(p.x(), p.y());
  const test::PolylineDistance polyline(poly);
  double worst = 0.0;
  for (size_t k = 1; k + 1 < out.size(); ++k) {
    const auto& curve = *out[k].curve;
    for (int i = 0; i <= 2; ++i) {
      const Vec3 p = curve.at(curve.length() * i / 2).position;
      const double best = polyline.distance(p.x(), p.y());
      worst = std::max(worst, std::abs(best - 2.0));
      EXPECT_NEAR(p.z(), -6.0, 1e-12);
    }
  }
  EXPECT_LT(worst, 1e-3);
  std::printf("thesis contour: %zu chords -> %zu tool-centre elements, worst distance error %.3g mm\n",
              points.size() - 1, out.size(), worst);
}

}  // namespace
}  // namespace drycut::interp
