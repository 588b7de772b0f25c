// Tool radius compensation on hand-built element streams, against hand-computed tool-centre
// points: squares and triangles with G41/G42 and G450/G451, approach and retract (NORM/KONT),
// arcs on both sides, order and metadata of the elements, and the alarms.
#include "interp/cutter_compensation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "cutter_compensation_test_support.hpp"
#include "interp/geometry/arc_curve.hpp"

namespace drycut::interp {
namespace {

using geometry::Vec3;
using test::Comp;
using test::line;
constexpr double kPi = std::numbers::pi;

using test::StageRun;

void expect_line(const PathElement& e, Vec3 a, Vec3 b, uint32_t block_line) {
  EXPECT_EQ(e.kind, ElementKind::Line);
  EXPECT_TRUE(e.curve->start().isApprox(a, 1e-9) || (e.curve->start() - a).norm() < 1e-9)
      << "start " << e.curve->start().transpose() << " expected " << a.transpose();
  EXPECT_LT((e.curve->end() - b).norm(), 1e-9) << "end " << e.curve->end().transpose() << " expected " << b.transpose();
  EXPECT_EQ(e.source.line, block_line);
}

void expect_arc(const PathElement& e, Vec3 centre, double radius, Vec3 a, Vec3 b, uint32_t block_line) {
  ASSERT_EQ(e.kind, ElementKind::Arc);
  EXPECT_LT((e.curve->start() - a).norm(), 1e-9) << e.curve->start().transpose();
  EXPECT_LT((e.curve->end() - b).norm(), 1e-9) << e.curve->end().transpose();
  for (int i = 0; i <= 4; ++i)
    EXPECT_NEAR((e.curve->at(e.curve->length() * i / 4).position - centre).norm(), radius, 1e-9);
  EXPECT_EQ(e.source.line, block_line);
}

// Square 20 x 20 counter-clockwise from (0,0), approach from (-10,-10), retract back there.
std::vector<PathElement> square(const Comp& comp) {
  return {line({-10, -10, 0}, {0, 0, 0}, comp, 1),  line({0, 0, 0}, {20, 0, 0}, comp, 2),
          line({20, 0, 0}, {20, 20, 0}, comp, 3),   line({20, 20, 0}, {0, 20, 0}, comp, 4),
          line({0, 20, 0}, {0, 0, 0}, comp, 5),     line({0, 0, 0}, {-10, -10, 0}, comp.off(), 6)};
}

TEST(CutterCompensation, PassesElementsUnchangedWhileInactive) {
  StageRun run;
  Comp off = Comp{}.off();
  auto a = line({0, 0, 0}, {5, 0, 0}, off, 1);
  const auto curve = a.curve;
  run.feed({a, test::non_motion(ElementKind::Dwell, off, 2), line({5, 0, 0}, {5, 5, 0}, off, 3)});
  ASSERT_EQ(run.sink.elements.size(), 3u);
  EXPECT_EQ(run.sink.elements[0].curve, curve);
  EXPECT_EQ(run.sink.elements[1].kind, ElementKind::Dwell);
  EXPECT_EQ(run.sink.elements[2].source.line, 3u);
  EXPECT_TRUE(run.sink.finished);
}

TEST(CutterCompensation, WorksInAPlaneAFrameTilted) {
  // The program's G17 plane turned by ROT X90 onto the machine's X/Z plane: first axis X,
  // normal (0, -1, 0). G41 offsets by normal x tangent: along +X that is (0, 0, 1), so the
  // contour X0..20 at Z0 runs at Z2; the left turn up +Z at X20 is an inside corner, offset
  // (-1, 0, 0): the two offset lines meet at (18, 0, 2). The approach ends normal to the first
  // contour element at (0, 0, 2).
  StageRun run;
  Comp comp{.side = CompensationSide::Left, .tilted = std::make_pair(Vec3(1, 0, 0), Vec3(0, -1, 0))};
  run.feed({line({-10, 0, -10}, {0, 0, 0}, comp, 1), line({0, 0, 0}, {20, 0, 0}, comp, 2),
            line({20, 0, 0}, {20, 0, 20}, comp, 3), line({20, 0, 20}, {10, 0, 30}, comp.off(), 4)});
  ASSERT_FALSE(run.diagnostics.has_alarms());
  const auto& out = run.sink.elements;
  ASSERT_GE(out.size(), 4u);
  expect_line(out[0], {-10, 0, -10}, {0, 0, 2}, 1);
  expect_line(out[1], {0, 0, 2}, {18, 0, 2}, 2);
  EXPECT_LT((out[2].curve->start() - Vec3(18, 0, 2)).norm(), 1e-9);
  EXPECT_LT((out[2].curve->end() - Vec3(18, 0, 20)).norm(), 1e-9);
}

TEST(CutterCompensation, SquareOutsideG42WithTransitionCircles) {
  StageRun run;
  Comp comp{.side = CompensationSide::Right};
  run.feed(square(comp));
  const auto& out = run.sink.elements;
  ASSERT_EQ(out.size(), 9u);
  expect_line(out[0], {-10, -10, 0}, {0, -2, 0}, 1);  // NORM: perpendicular to the first edge
  expect_line(out[1], {0, -2, 0}, {20, -2, 0}, 2);
  expect_arc(out[2], {20, 0, 0}, 2, {20, -2, 0}, {22, 0, 0}, 3);  // the circle belongs to the next block
  EXPECT_NEAR(out[2].curve->length(), kPi, 1e-9);
  EXPECT_LT((out[2].curve->at(kPi / 2).position - Vec3(20 + std::sqrt(2.0), -std::sqrt(2.0), 0)).norm(), 1e-9);
  expect_line(out[3], {22, 0, 0}, {22, 20, 0}, 3);
  expect_arc(out[4], {20, 20, 0}, 2, {22, 20, 0}, {20, 22, 0}, 4);
  expect_line(out[5], {20, 22, 0}, {0, 22, 0}, 4);
  expect_arc(out[6], {0, 20, 0}, 2, {0, 22, 0}, {-2, 20, 0}, 5);
  expect_line(out[7], {-2, 20, 0}, {-2, 0, 0}, 5);
  expect_line(out[8], {-2, 0, 0}, {-10, -10, 0}, 6);  // retract from the perpendicular end point
  test::expect_continuous(out);
  EXPECT_TRUE(run.diagnostics.items().empty());
}

TEST(CutterCompensation, SquareOutsideG42WithIntersections) {
  StageRun run;
  Comp comp{.side = CompensationSide::Right, .g451 = true};
  run.feed(square(comp));
  const auto& out = run.sink.elements;
  ASSERT_EQ(out.size(), 12u);
  expect_line(out[1], {0, -2, 0}, {20, -2, 0}, 2);
  expect_line(out[2], {20, -2, 0}, {22, -2, 0}, 3);  // to the offset lines' intersection
  expect_line(out[3], {22, -2, 0}, {22, 0, 0}, 3);
  expect_line(out[4], {22, 0, 0}, {22, 20, 0}, 3);
  expect_line(out[5], {22, 20, 0}, {22, 22, 0}, 4);
  expect_line(out[6], {22, 22, 0}, {20, 22, 0}, 4);
  expect_line(out[9], {-2, 22, 0}, {-2, 20, 0}, 5);
  expect_line(out[11], {-2, 0, 0}, {-10, -10, 0}, 6);
  test::expect_continuous(out);
}

TEST(CutterCompensation, SquareInsideG41TrimsAtTheIntersections) {
  for (bool g451 : {false, true}) {
    StageRun run;
    Comp comp{.side = CompensationSide::Left, .g451 = g451};
    auto elements = square(comp);
    elements.front() = line({10, 10, 0}, {0, 0, 0}, comp, 1);
    elements.back() = line({0, 0, 0}, {10, 10, 0}, comp.off(), 6);
    run.feed(elements);
    const auto& out = run.sink.elements;
    ASSERT_EQ(out.size(), 6u);
    expect_line(out[0], {10, 10, 0}, {0, 2, 0}, 1);
    expect_line(out[1], {0, 2, 0}, {18, 2, 0}, 2);
    expect_line(out[2], {18, 2, 0}, {18, 18, 0}, 3);
    expect_line(out[3], {18, 18, 0}, {2, 18, 0}, 4);
    expect_line(out[4], {2, 18, 0}, {2, 0, 0}, 5);
    expect_line(out[5], {2, 0, 0}, {10, 10, 0}, 6);
  }
}

// Right triangle (0,0) (10,0) (0,10 sqrt 3) counter-clockwise, starting down the Y edge so that all
// three corners are joints: direction changes 90 deg at (0,0), 120 at (10,0), 150 at the apex.
std::vector<PathElement> triangle(const Comp& comp, Vec3 approach_from) {
  const double h = 10 * std::sqrt(3.0);
  return {line(approach_from, {0, h, 0}, comp, 1), line({0, h, 0}, {0, 0, 0}, comp, 2),
          line({0, 0, 0}, {10, 0, 0}, comp, 3),   line({10, 0, 0}, {0, h, 0}, comp, 4),
          line({0, h, 0}, {0, 0, 0}, comp, 5),    line({0, 0, 0}, approach_from, comp.off(), 6)};
}

TEST(CutterCompensation, TriangleOutsideG451SwitchesToCircleAboveTheCornerLimit) {
  StageRun run;
  Comp comp{.side = CompensationSide::Right, .g451 = true};
  const double h = 10 * std::sqrt(3.0);
  run.feed(triangle(comp, {-10, h + 10, 0}));
  const auto& out = run.sink.elements;
  // approach, edge, 2 lines (90 deg), edge, arc (120 deg), edge, arc (150 deg), edge, retract
  ASSERT_EQ(out.size(), 10u);
  expect_line(out[1], {-2, h, 0}, {-2, 0, 0}, 2);
  expect_line(out[2], {-2, 0, 0}, {-2, -2, 0}, 3);
  expect_line(out[3], {-2, -2, 0}, {0, -2, 0}, 3);
  expect_line(out[4], {0, -2, 0}, {10, -2, 0}, 3);
  // Right of the direction (-1/2, sqrt3/2) is (sqrt3/2, 1/2).
  const Vec3 right_of_hypotenuse(std::sqrt(3.0) / 2, 0.5, 0);
  expect_arc(out[5], {10, 0, 0}, 2, {10, -2, 0}, Vec3(10, 0, 0) + 2 * right_of_hypotenuse, 4);
  EXPECT_NEAR(out[5].curve->length(), 2 * 2 * kPi / 3, 1e-9);
  expect_line(out[6], Vec3(10, 0, 0) + 2 * right_of_hypotenuse, Vec3(0, h, 0) + 2 * right_of_hypotenuse, 4);
  expect_arc(out[7], {0, h, 0}, 2, Vec3(0, h, 0) + 2 * right_of_hypotenuse, {-2, h, 0}, 5);
  EXPECT_NEAR(out[7].curve->length(), 2 * 5 * kPi / 6, 1e-9);
  test::expect_continuous(out);
}

TEST(CutterCompensation, TriangleOutsideG450UsesCirclesEverywhere) {
  StageRun run;
  Comp comp{.side = CompensationSide::Right};
  const double h = 10 * std::sqrt(3.0);
  run.feed(triangle(comp, {-10, h + 10, 0}));
  const auto& out = run.sink.elements;
  ASSERT_EQ(out.size(), 9u);
  expect_arc(out[2], {0, 0, 0}, 2, {-2, 0, 0}, {0, -2, 0}, 3);
  EXPECT_NEAR(out[2].curve->length(), kPi, 1e-9);
  test::expect_continuous(out);
}

TEST(CutterCompensation, TriangleInsideG41MeetsOnTheBisectors) {
  StageRun run;
  Comp comp{.side = CompensationSide::Left};
  const double h = 10 * std::sqrt(3.0);
  run.feed(triangle(comp, {3, 3, 0}));
  const auto& out = run.sink.elements;
  ASSERT_EQ(out.size(), 6u);
  // Corner (0,0), 90 deg inside: (2,2). Corner (10,0), 60 deg: 4 mm along the bisector
  // (-sqrt3/2, 1/2), i.e. (10 - 2 sqrt3, 2). Apex, 30 deg: r / sin 15deg along its bisector.
  expect_line(out[1], {2, h, 0}, {2, 2, 0}, 2);
  expect_line(out[2], {2, 2, 0}, {10 - 2 * std::sqrt(3.0), 2, 0}, 3);
  const double apex_distance = 2 / std::sin(kPi / 12);
  const Vec3 apex_bisector(std::sin(kPi / 12), -std::cos(kPi / 12), 0);
  expect_line(out[3], {10 - 2 * std::sqrt(3.0), 2, 0}, Vec3(0, h, 0) + apex_distance * apex_bisector, 4);
  expect_line(out[4], Vec3(0, h, 0) + apex_distance * apex_bisector, {2, 0, 0}, 5);
}

// Line, counter-clockwise half circle of radius 5 around (10,5), line back: tangential joints.
std::vector<PathElement> slot_end(const Comp& comp) {
  auto arc = std::make_shared<geometry::ArcCurve>(Vec3(10, 5, 0), 5.0, geometry::Plane::G17, -kPi / 2, kPi, 0.0);
  return {line({-5, 0, 0}, {0, 0, 0}, comp, 1), line({0, 0, 0}, {10, 0, 0}, comp, 2),
          test::motion(arc, ElementKind::Arc, comp, 3), line({10, 10, 0}, {0, 10, 0}, comp, 4),
          line({0, 10, 0}, {-5, 10, 0}, comp.off(), 5)};
}

TEST(CutterCompensation, ArcOffsetRadiusIsRadiusMinusOrPlusToolRadius) {
  for (auto side : {CompensationSide::Left, CompensationSide::Right}) {
    StageRun run;
    Comp comp{.side = side};
    run.feed(slot_end(comp));
    const auto& out = run.sink.elements;
    ASSERT_EQ(out.size(), 5u);  // tangential joints: no corner elements
    const double radius = side == CompensationSide::Left ? 3.0 : 7.0;
    expect_arc(out[2], {10, 5, 0}, radius, {10, 5 - radius, 0}, {10, 5 + radius, 0}, 3);
    EXPECT_NEAR(out[2].curve->length(), radius * kPi, 1e-9);
    test::expect_continuous(out);
  }
}

TEST(CutterCompensation, ArcTighterThanToolOnItsInsideRaisesCollisionAlarm) {
  StageRun run;
  Comp comp{.side = CompensationSide::Left, .radius = 6.0};
  try {
    run.feed(slot_end(comp));
    FAIL() << "no alarm";
  } catch (const AlarmError& e) {
    EXPECT_EQ(e.alarm().number, 10751);
    EXPECT_EQ(e.alarm().where.line, 3u);
  }
}

TEST(CutterCompensation, BottleneckSkipsTheShortStepWithWarning10763) {
  // A step up of 1 mm with a 2 mm tool on its inside: the circle around the step's upper corner
  // meets the first edge's offset at x = 10 - sqrt(3); the step block is cut out.
  StageRun run;
  Comp comp{.side = CompensationSide::Left};
  run.feed({line({0, -5, 0}, {0, 0, 0}, comp, 1), line({0, 0, 0}, {10, 0, 0}, comp, 2),
            line({10, 0, 0}, {10, 1, 0}, comp, 3), line({10, 1, 0}, {20, 1, 0}, comp, 4),
            line({20, 1, 0}, {20, -5, 0}, comp.off(), 5)});
  const auto& out = run.sink.elements;
  const double x = 10 - std::sqrt(3.0);
  ASSERT_EQ(out.size(), 5u);
  expect_line(out[1], {0, 2, 0}, {x, 2, 0}, 2);
  expect_arc(out[2], {10, 1, 0}, 2, {x, 2, 0}, {10, 3, 0}, 4);
  expect_line(out[3], {10, 3, 0}, {20, 3, 0}, 4);
  test::expect_continuous(out);
  ASSERT_EQ(run.diagnostics.items().size(), 1u);
  EXPECT_EQ(run.diagnostics.items()[0].number, 10763);
  EXPECT_EQ(run.diagnostics.items()[0].severity, Severity::Warning);
  EXPECT_EQ(run.diagnostics.items()[0].where.line, 3u);
  EXPECT_EQ(run.diagnostics.items()[0].block, "N30");
  // The detail names the two blocks whose tool-centre paths cross.
  EXPECT_NE(run.diagnostics.items()[0].text.find("crosses itself between TEST.MPF:2 and TEST.MPF:4"), std::string::npos)
      << run.diagnostics.items()[0].text;
}

TEST(CutterCompensation, InsideRoundingOfTheToolRadiusIsNoSkippedBlock) {
  // RND=2 with a 2 mm tool on the inside (a pocket's corner rounded to the cutter): the rounding's
  // offset is the point (8, 2); nothing of the path is lost, so no 10763 (a probe's shop program
  // listed every corner of a pocket as a skipped block).
  StageRun run;
  Comp comp{.side = CompensationSide::Left};
  auto rounding = std::make_shared<geometry::ArcCurve>(Vec3(8, 2, 0), 2.0, geometry::Plane::G17, -kPi / 2, kPi / 2, 0.0);
  run.feed({line({0, -5, 0}, {0, 0, 0}, comp, 1), line({0, 0, 0}, {8, 0, 0}, comp, 2),
            test::motion(rounding, ElementKind::Arc, comp, 3), line({10, 2, 0}, {10, 10, 0}, comp, 4),
            line({10, 10, 0}, {20, 10, 0}, comp.off(), 5)});
  const auto& out = run.sink.elements;
  test::expect_continuous(out);
  // The tool centre runs along y = 2 to the corner point (8, 2) and on along x = 8.
  ASSERT_EQ(out.size(), 4u);  // approach, two offsets, retract: the rounding's point is no element
  expect_line(out[1], {0, 2, 0}, {8, 2, 0}, 2);
  expect_line(out[2], {8, 2, 0}, {8, 10, 0}, 4);
  EXPECT_EQ(run.diagnostics.warning_count(), 0u) << (run.diagnostics.items().empty() ? "" : run.diagnostics.items()[0].text);
}

TEST(CutterCompensation, BottleneckWithG451CutsAtTheIntersectionLine) {
  StageRun run;
  Comp comp{.side = CompensationSide::Left, .g451 = true};
  run.feed({line({0, -5, 0}, {0, 0, 0}, comp, 1), line({0, 0, 0}, {10, 0, 0}, comp, 2),
            line({10, 0, 0}, {10, 1, 0}, comp, 3), line({10, 1, 0}, {20, 1, 0}, comp, 4)});
  const auto& out = run.sink.elements;
  ASSERT_EQ(out.size(), 5u);
  expect_line(out[1], {0, 2, 0}, {8, 2, 0}, 2);
  expect_line(out[2], {8, 2, 0}, {8, 3, 0}, 4);
  expect_line(out[3], {8, 3, 0}, {10, 3, 0}, 4);
  expect_line(out[4], {10, 3, 0}, {20, 3, 0}, 4);
  EXPECT_EQ(run.diagnostics.warning_count(), 1u);
}

TEST(CutterCompensation, CdofAlsoFindsTheIntersectionBeyondTheNextBlock) {
  // CDOF searches the previous block and, failing that, earlier ones (MD20240): the step of the
  // bottleneck test is resolved the same way, circle meeting the first offset at x = 10 - sqrt(3).
  StageRun run;
  Comp comp{.side = CompensationSide::Left, .cdon = false};
  run.feed({line({0, -5, 0}, {0, 0, 0}, comp, 1), line({0, 0, 0}, {10, 0, 0}, comp, 2),
            line({10, 0, 0}, {10, 1, 0}, comp, 3), line({10, 1, 0}, {20, 1, 0}, comp, 4)});
  const auto& out = run.sink.elements;
  ASSERT_GE(out.size(), 2u);
  expect_line(out[1], {0, 2, 0}, {10 - std::sqrt(3.0), 2, 0}, 2);
  ASSERT_EQ(run.diagnostics.items().size(), 1u);
  EXPECT_EQ(run.diagnostics.items()[0].where.line, 3u);
}

TEST(CutterCompensation, SlotNarrowerThanTheToolIsSkippedWithWarnings) {
  // A 1 mm slot with a 2 mm tool on its inside: the approach (x = 0 up to the offset point
  // (0, 2)) meets the offset of the slot's lower wall (y = -1) at (0, -1); the slot blocks in
  // between are cut out (10763 for N20 and N30) and the tool continues along y = -1.
  StageRun run;
  Comp comp{.side = CompensationSide::Left};
  run.feed({line({0, -5, 0}, {0, 0, 0}, comp, 1), line({0, 0, 0}, {10, 0, 0}, comp, 2),
            line({10, 0, 0}, {10, 1, 0}, comp, 3), line({10, 1, 0}, {0, 1, 0}, comp, 4),
            line({0, 1, 0}, {-5, 1, 0}, comp, 5), line({-5, 1, 0}, {-5, 20, 0}, comp, 6),
            line({-5, 20, 0}, {-5, 30, 0}, comp, 7)});
  const auto& out = run.sink.elements;
  ASSERT_GE(out.size(), 2u);
  expect_line(out[0], {0, -5, 0}, {0, -1, 0}, 1);
  test::expect_continuous(out);
  for (const auto& e : out) EXPECT_TRUE(e.source.line != 2u && e.source.line != 3u) << e.source.line;
  ASSERT_EQ(run.diagnostics.items().size(), 2u);
  EXPECT_EQ(run.diagnostics.items()[0].number, 10763);
  EXPECT_EQ(run.diagnostics.items()[0].where.line, 2u);
  EXPECT_EQ(run.diagnostics.items()[1].where.line, 3u);
}

TEST(CutterCompensation, KontTravelsAroundTheStartPointFromBehind) {
  StageRun run;
  Comp comp{.side = CompensationSide::Left, .kont = true};
  run.feed({line({-5, -5, 0}, {0, 0, 0}, comp, 1), line({0, 0, 0}, {20, 0, 0}, comp, 2)});
  const auto& out = run.sink.elements;
  ASSERT_EQ(out.size(), 3u);
  const double s = std::sqrt(2.0);
  expect_line(out[0], {-5, -5, 0}, {-s, s, 0}, 1);  // perpendicular to the approach direction
  expect_arc(out[1], {0, 0, 0}, 2, {-s, s, 0}, {0, 2, 0}, 1);
  EXPECT_NEAR(out[1].curve->length(), 2 * kPi / 4, 1e-9);
  expect_line(out[2], {0, 2, 0}, {20, 2, 0}, 2);
}

TEST(CutterCompensation, NormApproachesPerpendicularToTheFirstElement) {
  StageRun run;
  Comp comp{.side = CompensationSide::Left};
  run.feed({line({-5, -5, 0}, {0, 0, 0}, comp, 1), line({0, 0, 0}, {20, 0, 0}, comp, 2)});
  const auto& out = run.sink.elements;
  ASSERT_EQ(out.size(), 2u);
  expect_line(out[0], {-5, -5, 0}, {0, 2, 0}, 1);
  expect_line(out[1], {0, 2, 0}, {20, 2, 0}, 2);
}

TEST(CutterCompensation, KontRetractGoesAroundTheEndPoint) {
  StageRun run;
  Comp comp{.side = CompensationSide::Left, .kont = true};
  run.feed({line({0, 5, 0}, {0, 0, 0}, comp, 1), line({0, 0, 0}, {20, 0, 0}, comp, 2),
            line({20, 0, 0}, {25, -5, 0}, comp.off(), 3)});
  const auto& out = run.sink.elements;
  ASSERT_EQ(out.size(), 4u);
  const double s = std::sqrt(2.0);
  expect_arc(out[2], {20, 0, 0}, 2, {20, 2, 0}, {20 + s, s, 0}, 3);
  expect_line(out[3], {20 + s, s, 0}, {25, -5, 0}, 3);
}

TEST(CutterCompensation, G40RightAfterSelectionCancelsIt) {
  StageRun run;
  Comp comp{.side = CompensationSide::Left};
  run.feed({line({0, 0, 0}, {5, 0, 0}, comp, 1), line({5, 0, 0}, {5, 5, 0}, comp.off(), 2)});
  const auto& out = run.sink.elements;
  ASSERT_EQ(out.size(), 2u);
  expect_line(out[0], {0, 0, 0}, {5, 0, 0}, 1);
  expect_line(out[1], {5, 0, 0}, {5, 5, 0}, 2);
}

TEST(CutterCompensation, NonMotionElementsRunAtTheJointBeforeTheCorner) {
  StageRun run;
  Comp comp{.side = CompensationSide::Right};
  auto elements = square(comp);
  elements.insert(elements.begin() + 2, test::non_motion(ElementKind::Dwell, comp, 20));
  run.feed(elements);
  const auto& out = run.sink.elements;
  ASSERT_EQ(out.size(), 10u);
  EXPECT_EQ(out[1].source.line, 2u);
  EXPECT_EQ(out[2].kind, ElementKind::Dwell);
  EXPECT_EQ(out[3].kind, ElementKind::Arc);
}

TEST(CutterCompensation, ZeroInPlaneMotionRunsAtTheToolCentrePoint) {
  StageRun run;
  Comp comp{.side = CompensationSide::Left};
  run.feed({line({0, -5, 0}, {0, 0, 0}, comp, 1), line({0, 0, 0}, {10, 0, 0}, comp, 2),
            line({10, 0, 0}, {10, 0, -3}, comp, 3), line({10, 0, -3}, {10, 10, -3}, comp, 4)});
  const auto& out = run.sink.elements;
  ASSERT_EQ(out.size(), 4u);
  expect_line(out[1], {0, 2, 0}, {8, 2, 0}, 2);
  expect_line(out[2], {8, 2, 0}, {8, 2, -3}, 3);
  expect_line(out[3], {8, 2, -3}, {8, 10, -3}, 4);
}

TEST(CutterCompensation, TooManyEmptyBlocksRaise10762) {
  for (int empties : {3, 4}) {
    StageRun run;
    Comp comp{.side = CompensationSide::Left};
    std::vector<PathElement> elements;
    elements.push_back(line({0, -5, 0}, {0, 0, 0}, comp, 1));
    elements.push_back(line({0, 0, 0}, {10, 0, 0}, comp, 2));
    elements.push_back(test::non_motion(ElementKind::Dwell, comp, 3));
    elements.push_back(test::non_motion(ElementKind::DynamicsChange, comp, 4));
    elements.push_back(line({10, 0, 0}, {10, 0, -1}, comp, 5));  // no in-plane motion: counts
    if (empties == 4) elements.push_back(test::non_motion(ElementKind::Stop, comp, 6));
    elements.push_back(line({10, 0, -1}, {10, 10, -1}, comp, 7));
    if (empties == 3) {
      EXPECT_NO_THROW(run.feed(elements));
    } else {
      try {
        run.feed(elements);
        FAIL() << "no alarm";
      } catch (const AlarmError& e) {
        EXPECT_EQ(e.alarm().number, 10762);
        EXPECT_EQ(e.alarm().where.line, 6u);
        EXPECT_EQ(e.alarm().where.file, "TEST.MPF");
      }
    }
  }
}

TEST(CutterCompensation, PlaneChangeWhileActiveRaises10757) {
  StageRun run;
  Comp comp{.side = CompensationSide::Left};
  Comp other = comp;
  other.plane_axis = 1;
  try {
    run.feed({line({0, -5, 0}, {0, 0, 0}, comp, 1), line({0, 0, 0}, {10, 0, 0}, comp, 2),
              line({10, 0, 0}, {10, 0, 10}, other, 3)});
    FAIL() << "no alarm";
  } catch (const AlarmError& e) {
    EXPECT_EQ(e.alarm().number, 10757);
  }
}

TEST(CutterCompensation, CompensatesInTheG18Plane) {
  // G18: plane Z/X, normal +Y. Travel +Z with G41: left is Y x Z = +X.
  StageRun run;
  Comp comp{.side = CompensationSide::Left, .plane_axis = 1};
  run.feed({line({-5, 0, -5}, {0, 0, 0}, comp, 1), line({0, 0, 0}, {0, 0, 10}, comp, 2)});
  const auto& out = run.sink.elements;
  ASSERT_EQ(out.size(), 2u);
  expect_line(out[1], {2, 0, 0}, {2, 0, 10}, 2);
}

TEST(CutterCompensation, KeepsFeedDynamicsAndLabelOfTheSourceBlock) {
  StageRun run;
  Comp comp{.side = CompensationSide::Right};
  auto elements = square(comp);
  elements[2].feed_mm_s = 7.0;
  elements[2].label = "G1 edge";
  elements[2].dynamics.exact_stop_this_block = true;  // G9 on the block that gets the circle
  run.feed(elements);
  const auto& out = run.sink.elements;
  ASSERT_EQ(out.size(), 9u);
  for (int i : {2, 3}) {
    EXPECT_EQ(out[i].feed_mm_s, 7.0);
    EXPECT_EQ(out[i].label, "G1 edge");
    EXPECT_EQ(out[i].source.text, "N30");
  }
  EXPECT_FALSE(out[2].dynamics.exact_stop_this_block);  // the circle is not the block's end
  EXPECT_TRUE(out[3].dynamics.exact_stop_this_block);
  EXPECT_EQ(out[1].feed_mm_s, 20.0);
}

}  // namespace
}  // namespace drycut::interp
