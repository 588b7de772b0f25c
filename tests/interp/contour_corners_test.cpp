// Chamfers and roundings between two straight blocks (contour_corners.hpp) on element streams
// from the real loader and interpreter, against hand-computed geometry:
//   90° corner at (10,0), RND=2: legs t = r·tan(45°) = 2, arc (8,0) → (10,2) about (8,2),
//   length π; the path shortens by 2t - π = 4 - π.
//   CHR=3 at 90°: chamfer (7,0) → (10,3), length 3√2.  CHF=2 at 90°: t = 2/(2·cos 45°) = √2.
//   60° turn, RND=5: t = 5·tan 30° = 5/√3, arc length 5·π/3.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "interp/contour_corners.hpp"
#include "interp/cutter_compensation.hpp"
#include "interp/geometry/arc_curve.hpp"
#include "interp_test_support.hpp"

namespace drycut::interp {
namespace {

using Eigen::Vector3d;
using testing::near;

constexpr double kPi = std::numbers::pi;

struct Corners {
  std::unique_ptr<testing::RunResult> run;
  std::vector<PathElement> m;  // motions
  std::vector<int> warnings;
};

Corners run_corners(const std::string& text) {
  Corners r;
  r.run = testing::run_program(text);
  EXPECT_FALSE(r.run->alarm) << r.run->alarm->format();
  r.m = r.run->sink.motions();
  for (const auto& a : r.run->diagnostics.items()) r.warnings.push_back(a.number);
  return r;
}

double feed_length(const std::vector<PathElement>& m) {
  double s = 0;
  for (const auto& e : m)
    if (!e.rapid) s += e.curve->length();
  return s;
}

TEST(ContourCorners, RoundingOfANinetyDegreeCorner) {
  Corners r = run_corners("G0 X0 Y0 Z0\nG1 X10 F600 RND=2\nY10\nM30\n");
  ASSERT_EQ(r.m.size(), 4u);
  EXPECT_TRUE(r.warnings.empty());
  EXPECT_TRUE(near(r.m[1].curve->end(), Vector3d(8, 0, 0)));
  const PathElement& arc = r.m[2];
  EXPECT_EQ(arc.kind, ElementKind::Arc);
  EXPECT_EQ(arc.label, "RND");
  EXPECT_EQ(arc.source.line, 2u);
  EXPECT_NEAR(arc.curve->length(), kPi, 1e-12);
  EXPECT_TRUE(near(arc.curve->start(), Vector3d(8, 0, 0)));
  EXPECT_TRUE(near(arc.curve->end(), Vector3d(10, 2, 0)));
  const auto& circle = dynamic_cast<const geometry::ArcCurve&>(*arc.curve);
  EXPECT_TRUE(near(circle.centre(), Vector3d(8, 2, 0)));
  EXPECT_NEAR(circle.radius(), 2, 1e-12);
  // Tangent at both ends: along +X into it, along +Y out of it.
  EXPECT_TRUE(near(arc.curve->at(0).tangent, Vector3d(1, 0, 0), 1e-12));
  EXPECT_TRUE(near(arc.curve->at(kPi).tangent, Vector3d(0, 1, 0), 1e-12));
  EXPECT_TRUE(near(r.m[3].curve->start(), Vector3d(10, 2, 0)));
  EXPECT_NEAR(feed_length(r.m), 20 - (4 - kPi), 1e-12);
  EXPECT_NEAR(arc.feed_mm_s, 10.0, 1e-12);  // F600 of the block leading away
  EXPECT_TRUE(near(r.run->end_position, Vector3d(10, 10, 0)));
}

TEST(ContourCorners, ChamferByLegAndByLength) {
  Corners chr = run_corners("G0 X0 Y0 Z0\nG1 X10 F600 CHR=3\nY10\nM30\n");
  ASSERT_EQ(chr.m.size(), 4u);
  EXPECT_EQ(chr.m[2].kind, ElementKind::Line);
  EXPECT_EQ(chr.m[2].label, "CHR");
  EXPECT_TRUE(near(chr.m[2].curve->start(), Vector3d(7, 0, 0)));
  EXPECT_TRUE(near(chr.m[2].curve->end(), Vector3d(10, 3, 0)));
  EXPECT_NEAR(chr.m[2].curve->length(), 3 * std::sqrt(2.0), 1e-12);

  Corners chf = run_corners("G0 X0 Y0 Z0\nG1 X10 F600 CHF=2\nY10\nM30\n");
  ASSERT_EQ(chf.m.size(), 4u);
  EXPECT_NEAR(chf.m[2].curve->length(), 2.0, 1e-12);
  EXPECT_TRUE(near(chf.m[2].curve->start(), Vector3d(10 - std::sqrt(2.0), 0, 0), 1e-12));
  EXPECT_TRUE(near(chf.m[2].curve->end(), Vector3d(10, std::sqrt(2.0), 0), 1e-12));
}

TEST(ContourCorners, SixtyDegreeTurn) {
  // Out of (10,0) along (cos 60°, sin 60°) for 10 mm.
  Corners r = run_corners("G0 X0 Y0 Z0\nG1 X10 F600 RND=5\nX15 Y=5*SQRT(3)\nM30\n");
  ASSERT_EQ(r.m.size(), 4u);
  const double t = 5 / std::sqrt(3.0);
  EXPECT_TRUE(near(r.m[2].curve->start(), Vector3d(10 - t, 0, 0), 1e-12));
  EXPECT_TRUE(near(r.m[2].curve->end(), Vector3d(10 + t / 2, t * std::sqrt(3.0) / 2, 0), 1e-12));
  EXPECT_NEAR(r.m[2].curve->length(), 5 * kPi / 3, 1e-12);
}

TEST(ContourCorners, ModalRoundingOverASquareUntilRndmZero) {
  // Square 10 x 10 from (0,0): RNDM=1 rounds the corners at (10,0), (10,10), (0,10); RNDM=0 in
  // the last side ends it. Each rounding: legs 1, arc π/2; feed path 40 - 3·(2 - π/2).
  Corners r = run_corners("G0 X0 Y0 Z0\nG1 X10 F600 RNDM=1\nY10\nX0\nY0 RNDM=0\nX-5\nM30\n");
  ASSERT_EQ(r.m.size(), 9u);
  EXPECT_TRUE(r.warnings.empty());
  const char* labels[] = {"G0", "G1", "RNDM", "G1", "RNDM", "G1", "RNDM", "G1", "G1"};
  for (size_t i = 0; i < r.m.size(); ++i) EXPECT_EQ(r.m[i].label, labels[i]) << i;
  EXPECT_TRUE(near(r.m[3].curve->start(), Vector3d(10, 1, 0)));
  EXPECT_TRUE(near(r.m[3].curve->end(), Vector3d(10, 9, 0)));
  EXPECT_TRUE(near(r.m[7].curve->start(), Vector3d(0, 9, 0)));
  EXPECT_TRUE(near(r.m[7].curve->end(), Vector3d(0, 0, 0)));
  EXPECT_NEAR(feed_length(r.m), 45 - 3 * (2 - kPi / 2), 1e-12);
}

TEST(ContourCorners, FrcGivesTheRoundingItsFeed) {
  Corners r = run_corners("G0 X0 Y0 Z0\nG1 X10 F600 RND=2 FRC=120\nY10 F900\nM30\n");
  ASSERT_EQ(r.m.size(), 4u);
  EXPECT_NEAR(r.m[2].feed_mm_s, 2.0, 1e-12);
  EXPECT_NEAR(r.m[3].feed_mm_s, 15.0, 1e-12);
  Corners m = run_corners("G0 X0 Y0 Z0\nG1 X10 F600 RND=2 FRCM=60\nY10 RND=1\nX20\nM30\n");
  ASSERT_EQ(m.m.size(), 6u);
  EXPECT_NEAR(m.m[2].feed_mm_s, 1.0, 1e-12);
  EXPECT_NEAR(m.m[4].feed_mm_s, 1.0, 1e-12);
}

TEST(ContourCorners, OtherPlanes) {
  // G18: plane Z/X, normal Y. Corner at (0,0,10): along +Z, then +X.
  Corners r = run_corners("G0 X0 Y0 Z0\nG18 G1 Z10 F600 RND=2\nX10\nM30\n");
  ASSERT_EQ(r.m.size(), 4u);
  EXPECT_TRUE(near(r.m[2].curve->start(), Vector3d(0, 0, 8)));
  EXPECT_TRUE(near(r.m[2].curve->end(), Vector3d(2, 0, 10)));
  EXPECT_NEAR(r.m[2].curve->length(), kPi, 1e-12);
}

TEST(ContourCorners, ValueReducedWhereTheBlockIsTooShort) {
  // The first block is 1 mm long: RND=5 (legs 5) is reduced to legs 1, i.e. r = 1; the first
  // block vanishes, the rounding runs (0,0) → (1,1).
  Corners r = run_corners("G0 X0 Y0 Z0\nG1 X1 F600 RND=5\nY10\nM30\n");
  ASSERT_EQ(r.m.size(), 3u);
  EXPECT_EQ(r.m[1].label, "RND");
  EXPECT_NEAR(r.m[1].curve->length(), kPi / 2, 1e-12);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_EQ(r.warnings[0], 990015);
}

TEST(ContourCorners, RoundingBetweenALineAndACircle) {
  // Line +Y into C (10, 0), then G3 about O (10, 10), R 10, leaving C along +X: a right turn of
  // 90°. The rounding (r 2) lies on the right of both: its centre M is 2 off the line, x = 12,
  // and 12 from O (the inside of the turn is away from O): (12 - 10)² + (y - 10)² = 144,
  // y = 10 - √140 (the solution nearest C). P1 = (10, y) on the line, P2 = O + 10·(M - O)/12.
  Corners r = run_corners("G0 X10 Y-10 Z0\nG1 Y0 RND=2 F600\nG3 X20 Y10 CR=10\nM30\n");
  ASSERT_EQ(r.m.size(), 4u);
  EXPECT_TRUE(r.warnings.empty());
  const double y = 10 - std::sqrt(140.0);
  const Vector3d m(12, y, 0), o(10, 10, 0);
  const Vector3d p2 = o + 10 * (m - o) / 12;
  EXPECT_TRUE(near(r.m[1].curve->end(), Vector3d(10, y, 0)));
  const PathElement& arc = r.m[2];
  EXPECT_EQ(arc.label, "RND");
  const auto& circle = dynamic_cast<const geometry::ArcCurve&>(*arc.curve);
  EXPECT_TRUE(near(circle.centre(), m));
  EXPECT_NEAR(circle.radius(), 2.0, 1e-12);
  EXPECT_TRUE(near(arc.curve->end(), p2));
  EXPECT_TRUE(near(r.m[3].curve->start(), p2));
  EXPECT_TRUE(near(r.m[3].curve->end(), Vector3d(20, 10, 0)));
  // Tangent at both joints.
  for (size_t i = 1; i + 1 < r.m.size(); ++i)
    EXPECT_TRUE(near(r.m[i].curve->at(r.m[i].curve->length()).tangent, r.m[i + 1].curve->at(0).tangent)) << i;
}

TEST(ContourCorners, RoundingBetweenTwoCirclesAndFromACircleToALine) {
  // Invariants of the rounding (any geometry): it has radius r, its centre is r from the line or
  // R ± r from each circle's centre, and the path stays tangent at both joints.
  for (const char* text : {"G0 X0 Y0 Z0\nG2 X10 Y0 CR=5 F600 RND=2\nG1 X20\nM30\n",
                           "G0 X0 Y0 Z0\nG3 X10 Y0 CR=6 F600 RND=1.5\nG3 X20 Y0 CR=6\nM30\n",
                           "G0 X0 Y0 Z0\nG1 X10 F600 RND=2\nG3 X20 Y0 CR=5\nM30\n"}) {
    Corners r = run_corners(text);
    EXPECT_TRUE(r.warnings.empty()) << text;
    ASSERT_EQ(r.m.size(), 4u) << text;
    const auto& rounding = dynamic_cast<const geometry::ArcCurve&>(*r.m[2].curve);
    EXPECT_EQ(r.m[2].label, "RND") << text;
    for (const size_t side : {size_t{1}, size_t{3}}) {
      if (const auto* c = dynamic_cast<const geometry::ArcCurve*>(r.m[side].curve.get())) {
        const double d = (rounding.centre() - c->centre()).norm();
        EXPECT_NEAR(std::abs(d - c->radius()), rounding.radius(), 1e-9) << text;
      } else {
        const Vector3d a = r.m[side].curve->start(), b = r.m[side].curve->end();
        const Vector3d u = (b - a).normalized();
        const Vector3d q = rounding.centre() - a;
        EXPECT_NEAR((q - q.dot(u) * u).norm(), rounding.radius(), 1e-9) << text;
      }
    }
    for (size_t i = 1; i + 1 < r.m.size(); ++i)
      EXPECT_TRUE(near(r.m[i].curve->at(r.m[i].curve->length()).tangent, r.m[i + 1].curve->at(0).tangent, 1e-9))
          << text << " joint " << i;
  }
}

TEST(ContourCorners, NotModelledCasesKeepTheCornerAndWarn) {
  // A chamfer before a circle; a block with a third-axis component; no following motion.
  for (const char* text : {"G0 X0 Y0 Z0\nG1 X10 F600 CHF=2\nG3 X20 Y0 CR=5\nM30\n",
                           "G0 X0 Y0 Z0\nG1 X10 Z5 F600 RND=2\nY10\nM30\n",
                           "G0 X0 Y0 Z0\nG1 X10 F600 RND=2\nM30\n"}) {
    Corners r = run_corners(text);
    ASSERT_FALSE(r.warnings.empty()) << text;
    EXPECT_EQ(r.warnings[0], 990002) << text;
    for (const auto& e : r.m) EXPECT_NE(e.label, "RND") << text;
  }
}

TEST(ContourCorners, NoCornerAfterMoreThanThreeBlocksOrForParallelBlocks) {
  Corners far = run_corners("G0 X0 Y0 Z0\nG1 X10 F600 RND=2\nM8\nM9\nM8\nM9\nY10\nM30\n");
  EXPECT_EQ(far.m.size(), 3u);
  Corners three = run_corners("G0 X0 Y0 Z0\nG1 X10 F600 RND=2\nM8\nM9\nM8\nY10\nM30\n");
  EXPECT_EQ(three.m.size(), 4u);
  Corners straight = run_corners("G0 X0 Y0 Z0\nG1 X10 F600 RND=2\nX20\nM30\n");
  EXPECT_EQ(straight.m.size(), 3u);
  EXPECT_TRUE(straight.warnings.empty());
}

TEST(ContourCorners, ToolRadiusCompensationOffsetsTheRounding) {
  // G41 on a counter-clockwise square: the tool (test profile T1 D1, r = 2) runs inside. The
  // rounding RND=5 at (20,0) (arc (15,0) -> (20,5) about (15,5)) becomes the concentric arc of
  // radius 5 - 2 = 3 from (15,2) to (18,5) on the tool centre path (Z 50: the tool length 50
  // is added to the carrier position).
  Corners r = run_corners("T1 D1 M6\nG0 X-10 Y-10 Z0\nG1 G41 X0 Y0 F600\nX20 RND=5\nY20\nX0\nG40 X-10 Y-10\nM30\n");
  ASSERT_TRUE(r.warnings.empty());
  testing::CollectingSink centre;
  Diagnostics diagnostics;
  const auto profile = testing::test_profile();
  CutterCompensation stage(centre, profile, diagnostics);
  for (auto& e : r.run->sink.elements) stage.consume(PathElement(e));
  stage.finish();
  const PathElement* arc = nullptr;
  for (const auto& e : centre.elements)
    if (e.label == "RND") arc = &e;
  ASSERT_NE(arc, nullptr);
  const auto& circle = dynamic_cast<const geometry::ArcCurve&>(*arc->curve);
  EXPECT_TRUE(near(circle.centre(), Vector3d(15, 5, 50), 1e-9));
  EXPECT_NEAR(circle.radius(), 3, 1e-9);
  EXPECT_TRUE(near(arc->curve->start(), Vector3d(15, 2, 50), 1e-9));
  EXPECT_TRUE(near(arc->curve->end(), Vector3d(18, 5, 50), 1e-9));
}

TEST(ContourCorners, LegFormulas) {
  const double theta = kPi / 2;
  EXPECT_NEAR(corner_leg(ContourCornerKind::Round, 2, theta), 2, 1e-12);
  EXPECT_NEAR(corner_leg(ContourCornerKind::Chamfer, 2, theta), std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(corner_leg(ContourCornerKind::ChamferLeg, 2, theta), 2, 1e-12);
  for (auto k : {ContourCornerKind::Round, ContourCornerKind::Chamfer, ContourCornerKind::ChamferLeg})
    EXPECT_NEAR(corner_size_for_leg(k, corner_leg(k, 3, 1.0), 1.0), 3, 1e-12);
}

}  // namespace
}  // namespace drycut::interp
