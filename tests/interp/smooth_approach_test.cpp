// The SAR sub-movements (interp/smooth_approach.hpp) against points computed by hand (G17: the
// normal is +Z, the contour starts at P4 = (25, 0, -5) going +Y unless a test says otherwise).
#include <gtest/gtest.h>

#include <numbers>

#include "interp/geometry/arc_curve.hpp"
#include "interp/smooth_approach.hpp"

namespace drycut::interp {
namespace {

using geometry::Vec3;

const Vec3 kNormal(0, 0, 1);
const Vec3 kP4(25, 0, -5);
const Vec3 kUp(0, 1, 0);

void expect_near(const Vec3& a, const Vec3& b) { EXPECT_LT((a - b).norm(), 1e-9) << a.transpose() << " vs " << b.transpose(); }

SarRequest request(SarShape shape, bool in_plane, double disr, double clearance_height, int side_rule = 140) {
  SarRequest r;
  r.shape = shape;
  r.in_plane = in_plane;
  r.disr_mm = disr;
  r.clearance_height = clearance_height;
  r.side_rule = side_rule;
  return r;
}

// G41 (left, r = 5) G247 G341 DISR=10 DISCL=2: left of +Y is -X; the tool-centre circle of
// radius 10 is the contour circle of radius 15 about (10, 0); the quadrant starts 15 behind the
// centre along -t: (10, -15). P0 (0, 0, 10) -> P1 (10, -15, 10) -> P2 (10, -15, -3) -> P3
// (10, -15, -5) -> the quadrant to P4, counter-clockwise (sweep +90 degrees).
TEST(SmoothApproach, QuadrantInThePlaneFromTheToolSide) {
  const auto pieces = approach_pieces(Vec3(0, 0, 10), kP4, kUp, kNormal, request(SarShape::Quadrant, true, 10, -3), 5, 1);
  ASSERT_EQ(pieces.size(), 4u);
  expect_near(pieces[0].curve->end(), Vec3(10, -15, 10));
  EXPECT_EQ(pieces[0].speed, SarSpeed::Before);
  expect_near(pieces[1].curve->end(), Vec3(10, -15, -3));
  EXPECT_EQ(pieces[1].speed, SarSpeed::Before);
  expect_near(pieces[2].curve->end(), Vec3(10, -15, -5));
  EXPECT_EQ(pieces[2].speed, SarSpeed::Fad);
  const auto* arc = dynamic_cast<const geometry::ArcCurve*>(pieces[3].curve.get());
  ASSERT_NE(arc, nullptr);
  EXPECT_TRUE(pieces[3].contour);
  EXPECT_EQ(pieces[3].speed, SarSpeed::Own);
  EXPECT_NEAR(arc->radius(), 15, 1e-12);
  EXPECT_NEAR(arc->sweep(), std::numbers::pi / 2, 1e-12);
  expect_near(arc->end(), kP4);
  expect_near(arc->end_tangent(), kUp);  // joins the contour tangentially
}

// G340 (in space), semicircle without compensation, DISR=8, clearance at Z-3, approach from the
// right (G142): the circle's centre is P4 + 8 * (+X) = (33, 0), the semicircle starts at (41, 0)
// going -Y and turns clockwise (sweep -180 degrees) down from Z-3 to Z-5: a helix.
TEST(SmoothApproach, SemicircleInSpaceIsAHelix) {
  const auto pieces =
      approach_pieces(Vec3(0, 0, 10), kP4, kUp, kNormal, request(SarShape::Semicircle, false, 8, -3, 142), 0, 0);
  ASSERT_EQ(pieces.size(), 3u);
  expect_near(pieces[0].curve->end(), Vec3(41, 0, 10));
  expect_near(pieces[1].curve->end(), Vec3(41, 0, -3));
  const auto* arc = dynamic_cast<const geometry::ArcCurve*>(pieces[2].curve.get());
  ASSERT_NE(arc, nullptr);
  EXPECT_EQ(pieces[2].speed, SarSpeed::Fad);  // G340: the descending contour at FAD
  EXPECT_NEAR(arc->radius(), 8, 1e-12);
  EXPECT_NEAR(arc->sweep(), -std::numbers::pi, 1e-12);
  EXPECT_NEAR(arc->axial_travel(), -2, 1e-12);
  expect_near(arc->start(), Vec3(41, 0, -3));
  expect_near(arc->end(), kP4);
  // Its length: sqrt((8 pi)^2 + 2^2).
  EXPECT_NEAR(arc->length(), std::hypot(8 * std::numbers::pi, 2.0), 1e-9);
}

// G147 with G42 (r = 4), DISR=6: the line is DISR + r = 10 long on the contour, along t; G143
// and G140 play no part for a line. G341 with the clearance at P4's plane: no infeed piece.
TEST(SmoothApproach, StraightLineIsDisrPlusTheRadius) {
  const auto pieces = approach_pieces(Vec3(25, -30, -5), kP4, kUp, kNormal, request(SarShape::Line, true, 6, -5), 4, -1);
  ASSERT_EQ(pieces.size(), 2u);
  expect_near(pieces[0].curve->end(), Vec3(25, -10, -5));
  expect_near(pieces[1].curve->start(), Vec3(25, -10, -5));
  expect_near(pieces[1].curve->end(), kP4);
}

// G143: the side the start point lies on. P0 right of the tangent (+X of the line x = 25 going
// +Y): the quadrant comes from the right, centre (25 + 10, 0), clockwise.
TEST(SmoothApproach, AutomaticSideFollowsTheStartPoint) {
  const auto pieces =
      approach_pieces(Vec3(60, -20, 10), kP4, kUp, kNormal, request(SarShape::Quadrant, true, 10, -5, 143), 0, 0);
  const auto* arc = dynamic_cast<const geometry::ArcCurve*>(pieces.back().curve.get());
  ASSERT_NE(arc, nullptr);
  expect_near(arc->centre(), Vec3(35, 0, -5));
  EXPECT_LT(arc->sweep(), 0.0);
}

// Retraction after a contour ending at P4 going +Y, G41 (r = 5) left, with G40: G248 G341
// DISR=10 DISCL=2 to P0 (0, 0, 10), on the tool centre. The contour end's offset is (20, 0); the
// quadrant of radius 10 about (10, 0) leaves it to the left, to (10, 10). Then up at FAD to
// Z-3, up to Z10, across to P0.
TEST(SmoothApproach, RetractionWithG40RunsOnTheToolCentre) {
  const Vec3 p0(0, 0, 10);
  const auto pieces =
      retraction_pieces(kP4, kUp, &p0, 10, kNormal, request(SarShape::Quadrant, true, 10, -3), 5, 1, true);
  ASSERT_EQ(pieces.size(), 4u);
  EXPECT_TRUE(pieces[0].contour);
  EXPECT_EQ(pieces[0].speed, SarSpeed::Before);
  expect_near(pieces[0].curve->start(), Vec3(20, 0, -5));
  expect_near(pieces[0].curve->end(), Vec3(10, 10, -5));
  expect_near(pieces[1].curve->start(), Vec3(10, 10, -5));
  expect_near(pieces[1].curve->end(), Vec3(10, 10, -3));
  EXPECT_EQ(pieces[1].speed, SarSpeed::Fad);
  expect_near(pieces[2].curve->end(), Vec3(10, 10, 10));
  expect_near(pieces[3].curve->end(), p0);
  EXPECT_EQ(pieces[3].speed, SarSpeed::Own);
}

// The same retraction keeping G41 (no G40 in the block): on the programmed contour, the
// quadrant of contour radius DISR + r = 15 about (10, 0) to (10, 15), the rest from there (the
// compensation offsets it all).
TEST(SmoothApproach, RetractionKeepingTheCompensationRunsOnTheContour) {
  const Vec3 p0(0, 0, 10);
  const auto pieces =
      retraction_pieces(kP4, kUp, &p0, 10, kNormal, request(SarShape::Quadrant, true, 10, -3), 5, 1, false);
  ASSERT_EQ(pieces.size(), 4u);
  expect_near(pieces[0].curve->start(), kP4);
  expect_near(pieces[0].curve->end(), Vec3(10, 15, -5));
  expect_near(pieces[1].curve->end(), Vec3(10, 15, -3));
  expect_near(pieces[3].curve->end(), p0);
}

// A retraction block that names no axis of the plane (G248 ... Z5) ends above the contour's end.
TEST(SmoothApproach, RetractionWithoutPlaneAxesEndsAboveTheContour) {
  const auto pieces =
      retraction_pieces(kP4, kUp, nullptr, 5, kNormal, request(SarShape::Line, false, 3, -3), 0, 0, true);
  ASSERT_EQ(pieces.size(), 2u);
  expect_near(pieces[0].curve->end(), Vec3(25, 3, -3));  // G340: rising along the line
  expect_near(pieces[1].curve->end(), Vec3(25, 3, 5));
}

TEST(SmoothApproach, NoDirectionInThePlaneGivesNoPieces) {
  EXPECT_TRUE(approach_pieces(Vec3(0, 0, 10), kP4, kNormal, kNormal, request(SarShape::Quadrant, true, 10, -3), 0, 0)
                  .empty());
}

}  // namespace
}  // namespace drycut::interp
