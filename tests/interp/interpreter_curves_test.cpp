// Arcs and splines through the interpreter: closed forms and invariants.
#include <cmath>
#include <numbers>

#include "interp_test_support.hpp"

namespace drycut::interp::testing {
namespace {

using Eigen::Vector3d;
constexpr double kPi = std::numbers::pi;

TEST(InterpreterArcs, FullCircleWithIJ) {
  auto r = run_program("G0 X0 Y0 Z0\nG2 I10 F600\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  auto m = r->sink.motions();
  ASSERT_EQ(m.size(), 2u);
  EXPECT_NEAR(m[1].curve->length(), 2 * kPi * 10, 1e-6);
  EXPECT_TRUE(near(m[1].curve->end(), Vector3d(0, 0, 0), 1e-9));
  // Clockwise around (10, 0) from (0, 0): heading +Y first.
  EXPECT_GT(m[1].curve->at(0).tangent.y(), 0.99);
}

TEST(InterpreterArcs, RadiusProgrammingPicksTheShortOrLongArc) {
  auto s = run_program("G0 X0 Y0 Z0\nG3 X20 Y0 CR=10 F600\nM30\n");
  ASSERT_FALSE(s->alarm) << s->alarm->format();
  EXPECT_NEAR(s->sink.motions()[1].curve->length(), kPi * 10, 1e-6);  // semicircle
  auto l = run_program("G0 X0 Y0 Z0\nG3 X10 Y10 CR=-10 F600\nM30\n");
  ASSERT_FALSE(l->alarm) << l->alarm->format();
  EXPECT_NEAR(l->sink.motions()[1].curve->length(), 1.5 * kPi * 10, 1e-6);  // 270°
}

TEST(InterpreterArcs, HelixLengthIsTheClosedForm) {
  // Quarter circle r=10 with 5 mm along Z: L = sqrt((r*phi)^2 + h^2).
  auto r = run_program("G0 X10 Y0 Z0\nG3 X0 Y10 Z5 I-10 J0 F600\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  EXPECT_NEAR(r->sink.motions()[1].curve->length(), std::hypot(10 * kPi / 2, 5.0), 1e-6);
}

TEST(InterpreterArcs, CentreAbsoluteWithAC) {
  auto r = run_program("G0 X10 Y0 Z0\nG3 X-10 Y0 I=AC(0) J=AC(0) F600\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  EXPECT_NEAR(r->sink.motions()[1].curve->length(), kPi * 10, 1e-6);
}

TEST(InterpreterArcs, EndPointErrorIsAlarm14040) {
  // Start radius 3, end radius 7: far outside the 0.01 mm tolerance.
  auto r = run_program("G0 X0 Y0 Z0\nG2 X10 Y0 I3 F600\nM30\n");
  ASSERT_TRUE(r->alarm);
  EXPECT_EQ(r->alarm->number, 14040);
  EXPECT_EQ(r->alarm->where.line, 2u);
}

TEST(InterpreterArcs, TangentialArcContinuesThePreviousDirection) {
  auto r = run_program("G0 X0 Y0 Z0\nG1 X10 F600\nCT X20 Y10\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  auto m = r->sink.motions();
  ASSERT_EQ(m.size(), 3u);
  EXPECT_TRUE(near(m[2].curve->at(0).tangent, Vector3d(1, 0, 0), 1e-9));
  EXPECT_NEAR(m[2].curve->length(), 10 * kPi / 2, 1e-6);  // quarter circle of radius 10
}

TEST(InterpreterArcs, CircleThroughAnIntermediatePoint) {
  auto r = run_program("G0 X10 Y0 Z0\nCIP X-10 Y0 I1=0 J1=10 F600\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  EXPECT_NEAR(r->sink.motions()[1].curve->length(), kPi * 10, 1e-6);
}

TEST(InterpreterSplines, AkimaPassesThroughEveryProgrammedPoint) {
  const std::vector<Vector3d> pts{{1, 1, 0}, {2, 0.5, 0}, {3, 2, 0}, {4, 1, 0}, {5, 1.5, 0}, {6, 0, 0}};
  std::string text = "G0 X0 Y0 Z0\nG1 F600\nASPLINE\n";
  for (const auto& p : pts) text += "X" + std::to_string(p.x()) + " Y" + std::to_string(p.y()) + "\n";
  text += "G1 X7 Y0\nM30\n";
  auto r = run_program(text);
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  auto m = r->sink.motions();
  ASSERT_EQ(m.size(), 1u + pts.size() + 1u);
  for (size_t i = 0; i < pts.size(); ++i) {
    EXPECT_EQ(m[1 + i].kind, ElementKind::SplineSpan);
    EXPECT_EQ(m[1 + i].label, "ASPLINE");
    EXPECT_EQ(m[1 + i].source.line, 4u + i);  // each span belongs to its block
    EXPECT_TRUE(near(m[1 + i].curve->end(), pts[i], 1e-9));
  }
  // Consecutive spans join tangentially (C1).
  for (size_t i = 1; i + 1 < pts.size(); ++i)
    EXPECT_TRUE(near(m[i].curve->at(m[i].curve->length()).tangent, m[i + 1].curve->at(0).tangent, 1e-6)) << i;
}

TEST(InterpreterSplines, BtanTakesThePrecedingDirectionAndEtanTheFollowing) {
  auto r = run_program("G0 X0 Y0 Z0\nG1 X10 Y0 F600\nBTAN ETAN\nCSPLINE\nX15 Y3\nX20 Y2\nX25 Y6\nG1 X25 Y20\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  auto m = r->sink.motions();
  ASSERT_EQ(m.size(), 6u);
  EXPECT_TRUE(near(m[2].curve->at(0).tangent, Vector3d(1, 0, 0), 1e-6));
  const auto& last = m[4];
  EXPECT_TRUE(near(last.curve->at(last.curve->length()).tangent, Vector3d(0, 1, 0), 1e-6));
}

TEST(InterpreterSplines, EqualWeightsOnAllPointsChangeNothing) {
  const std::string pts = "X5 Y5\nX10 Y0\nX15 Y5\nX20 Y0\nX25 Y5\nX30 Y0\n";
  auto plain = run_program("G0 X0 Y0 Z0\nG1 F600\nBSPLINE\n" + pts + "M30\n");
  std::string weighted = "G0 X0 Y0 Z0\nG1 F600\nBSPLINE\n";
  for (size_t pos = 0, next; (next = pts.find('\n', pos)) != std::string::npos; pos = next + 1)
    weighted += pts.substr(pos, next - pos) + " PW=3\n";
  auto w = run_program(weighted + "M30\n");
  ASSERT_FALSE(plain->alarm) << plain->alarm->format();
  ASSERT_FALSE(w->alarm) << w->alarm->format();
  auto a = plain->sink.motions(), b = w->sink.motions();
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 1; i < a.size(); ++i) {
    EXPECT_NEAR(a[i].curve->length(), b[i].curve->length(), 1e-9);
    for (double f : {0.0, 0.3, 0.7, 1.0})
      EXPECT_TRUE(near(a[i].curve->at(f * a[i].curve->length()).position,
                       b[i].curve->at(f * b[i].curve->length()).position, 1e-9));
  }
  // The B spline ends on the last control point.
  EXPECT_TRUE(near(a.back().curve->end(), Vector3d(30, 0, 0), 1e-9));
}

TEST(InterpreterSplines, TooFewSplineBlocksInTenIsAnAlarm) {
  // A spline needs 4 end-point blocks in every window of 10; the window ending with X4 (line 14)
  // holds 3 of 10.
  std::string text = "G0 X0 Y0 Z0\nG1 F600\nASPLINE\nX1 Y1\nX2 Y0\nX3 Y1\n";
  for (int i = 0; i < 7; ++i) text += "M8\n";
  text += "X4 Y0\nM30\n";
  auto r = run_program(text);
  ASSERT_TRUE(r->alarm);
  EXPECT_EQ(r->alarm->number, 990001);
  EXPECT_EQ(r->alarm->where.line, 14u);
}

TEST(InterpreterSplines, QuotaIsNotJudgedAfterTheLastPointOfARun) {
  // Ending a C-spline run with non-spline blocks (M17, G40 ...) is fine, as in the experiment.
  std::string text = "G0 X0 Y0 Z0\nG1 F600\nCSPLINE\n";
  for (int i = 1; i <= 12; ++i) text += "X" + std::to_string(i) + " Y" + std::to_string(i % 2) + "\n";
  text += "M8\nM9\nG1 X20 Y0\nM30\n";
  auto r = run_program(text);
  EXPECT_FALSE(r->alarm) << r->alarm->format();
}

}  // namespace
}  // namespace drycut::interp::testing

namespace drycut::interp::testing {
namespace {

TEST(InterpreterSplines, BadWeightIsAnAlarmAtItsBlock) {
  auto r = run_program("G0 X0 Y0 Z0\nG1 F600\nBSPLINE\nX1 Y1 PW=4\nX2 Y0\nM30\n");
  ASSERT_TRUE(r->alarm);
  EXPECT_EQ(r->alarm->number, 12160);
  EXPECT_EQ(r->alarm->where.line, 4u);
}

}  // namespace
}  // namespace drycut::interp::testing

namespace drycut::interp::testing {
namespace {

TEST(InterpreterSplines, EtanBeforeAnArcTakesTheArcsStartTangent) {
  // G3 from (25,6) to (35,6) with CR=5: centre (30,6), counter-clockwise, leaving (25,6) along -Y.
  auto r = run_program("G0 X0 Y0 Z0\nG1 X10 Y0 F600\nBTAN ETAN\nCSPLINE\nX15 Y3\nX20 Y2\nX25 Y6\nG3 X35 Y6 CR=5\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  auto m = r->sink.motions();
  ASSERT_EQ(m.size(), 6u);
  const auto& last_span = m[4];
  EXPECT_TRUE(near(last_span.curve->at(last_span.curve->length()).tangent, Eigen::Vector3d(0, -1, 0), 1e-6));
  EXPECT_TRUE(near(m[5].curve->at(0).tangent, Eigen::Vector3d(0, -1, 0), 1e-9));
}

}  // namespace
}  // namespace drycut::interp::testing
