// OffsetCurve against closed forms: offsets of lines and arcs, helices (only the in-plane part is
// offset), parabolas (length L - d * turning angle; loop length with |1 - d kappa|), the sign
// convention of G41/G42 in all three planes, and the differential invariants of any Curve.
#include "interp/geometry/offset_curve.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "../compensation_test_curves.hpp"
#include "interp/geometry/arc_curve.hpp"
#include "interp/geometry/line_curve.hpp"

namespace drycut::geometry {
namespace {

constexpr double kPi = std::numbers::pi;
const Vec3 kZ = Vec3::UnitZ();

TEST(OffsetCurve, LineOffsetLiesLeftForPositiveOffset) {
  auto line = std::make_shared<LineCurve>(Vec3(0, 0, 0), Vec3(10, 0, 0));
  OffsetCurve left(line, 2.0, kZ), right(line, -2.0, kZ);
  EXPECT_NEAR(left.length(), 10.0, 1e-9);
  EXPECT_TRUE(left.start().isApprox(Vec3(0, 2, 0), 1e-12));
  EXPECT_TRUE(left.end().isApprox(Vec3(10, 2, 0), 1e-12));
  EXPECT_TRUE(right.at(5.0).position.isApprox(Vec3(5, -2, 0), 1e-12));
  EXPECT_NEAR(right.max_curvature(), 0.0, 1e-12);
}

TEST(OffsetCurve, LeftIsNormalCrossTangentInEveryPlane) {
  // G18: normal +Y, travel +Z -> left is Y x Z = +X. G19: normal +X, travel +Y -> left is +Z.
  auto along_z = std::make_shared<LineCurve>(Vec3(0, 0, 0), Vec3(0, 0, 10));
  EXPECT_TRUE(OffsetCurve(along_z, 2.0, Vec3::UnitY()).start().isApprox(Vec3(2, 0, 0), 1e-12));
  auto along_y = std::make_shared<LineCurve>(Vec3(0, 0, 0), Vec3(0, 10, 0));
  EXPECT_TRUE(OffsetCurve(along_y, 2.0, Vec3::UnitX()).start().isApprox(Vec3(0, 0, 2), 1e-12));
}

TEST(OffsetCurve, LineWithNormalTravelIsOffsetInPlaneOnly) {
  auto ramp = std::make_shared<LineCurve>(Vec3(0, 0, 0), Vec3(3, 4, -12));
  OffsetCurve off(ramp, 1.0, kZ);
  // In-plane direction (0.6, 0.8); left of it (-0.8, 0.6).
  EXPECT_TRUE(off.start().isApprox(Vec3(-0.8, 0.6, 0), 1e-12));
  EXPECT_TRUE(off.end().isApprox(Vec3(3 - 0.8, 4.6, -12), 1e-12));
  EXPECT_NEAR(off.length(), 13.0, 1e-9);
}

TEST(OffsetCurve, ArcConcaveAndConvexSideChangeTheRadius) {
  // Counter-clockwise quarter circle of radius 10: its left side is the centre side.
  auto arc = std::make_shared<ArcCurve>(Vec3(1, 2, 0), 10.0, Plane::G17, 0.0, kPi / 2, 0.0);
  for (double d : {2.0, -2.0}) {
    OffsetCurve off(arc, d, kZ);
    const double radius = 10.0 - d;
    EXPECT_NEAR(off.length(), radius * kPi / 2, 1e-6 * radius) << d;
    EXPECT_NEAR(off.max_curvature(), 1.0 / radius, 1e-9) << d;
    for (int i = 0; i <= 10; ++i) {
      const CurvePoint p = off.at(off.length() * i / 10);
      EXPECT_NEAR((p.position - Vec3(1, 2, 0)).norm(), radius, 1e-9);
      EXPECT_NEAR(p.curvature, 1.0 / radius, 1e-9);
      EXPECT_NEAR(p.curvature_derivative, 0.0, 1e-6);
      // Same angle as the base point at the same fraction of the length.
      const double angle = kPi / 2 * i / 10;
      EXPECT_TRUE(p.position.isApprox(Vec3(1 + radius * std::cos(angle), 2 + radius * std::sin(angle), 0), 1e-9));
    }
  }
}

TEST(OffsetCurve, HelixKeepsItsPitchAndChangesItsRadius) {
  // One clockwise turn of radius 10 falling 6 mm (G2 with Z): left of a clockwise arc is outside.
  auto helix = std::make_shared<ArcCurve>(Vec3(0, 0, 0), 10.0, Plane::G17, 0.0, -2 * kPi, -6.0);
  OffsetCurve off(helix, 2.0, kZ);
  const double radius = 12.0, pitch = -6.0 / (2 * kPi);
  EXPECT_NEAR(off.length(), std::hypot(radius * 2 * kPi, 6.0), 1e-6);
  EXPECT_NEAR(off.at(off.length() / 2).position.z(), -3.0, 1e-7);
  EXPECT_NEAR(off.max_curvature(), radius / (radius * radius + pitch * pitch), 1e-9);
  for (int i = 0; i <= 8; ++i) {
    const Vec3 p = off.at(off.length() * i / 8).position;
    EXPECT_NEAR(std::hypot(p.x(), p.y()), radius, 1e-9);
  }
}

TEST(OffsetCurve, ParabolaLengthIsBaseLengthMinusOffsetTimesTurning) {
  test::ParabolaCurve parabola(0.1, -3.0, 3.0);  // radius of curvature >= 5
  auto base = std::make_shared<test::ParabolaCurve>(parabola);
  const double turning = parabola.angle_at_x(3.0) - parabola.angle_at_x(-3.0);
  for (double d : {2.0, -2.0}) {
    OffsetCurve off(base, d, kZ);
    const double expected = parabola.length() - d * turning;
    EXPECT_LT(std::abs(off.length() - expected) / expected, 1e-6) << d;
    // At the vertex the offset's radius of curvature is 5 - d.
    const double s_vertex = [&] {
      // Arc length of the offset up to the vertex: half of the whole by symmetry.
      return 0.5 * off.length();
    }();
    EXPECT_NEAR(off.at(s_vertex).curvature, 1.0 / (5.0 - d), 1e-6) << d;
    EXPECT_TRUE(off.at(s_vertex).position.isApprox(Vec3(0, d, 0), 1e-7)) << d;
  }
}

TEST(OffsetCurve, DifferentialGeometryMatchesFiniteDifferences) {
  auto base = std::make_shared<test::ParabolaCurve>(0.1, -3.0, 3.0, 1.0);
  OffsetCurve off(base, 2.0, kZ);
  const double h = 1e-4;
  for (double s : {0.5, 2.0, off.length() / 2 + 0.3, off.length() - 1.0}) {
    const CurvePoint p = off.at(s), lo = off.at(s - h), hi = off.at(s + h);
    EXPECT_NEAR(p.tangent.norm(), 1.0, 1e-12);
    EXPECT_TRUE(((hi.position - lo.position) / (2 * h)).isApprox(p.tangent, 1e-7));
    EXPECT_LT((((hi.tangent - lo.tangent) / (2 * h)) - p.curvature_vector).norm(), 1e-6);
    EXPECT_LT((((hi.curvature_vector - lo.curvature_vector) / (2 * h)) - p.curvature_rate).norm(), 1e-5);
    EXPECT_NEAR((hi.curvature - lo.curvature) / (2 * h), p.curvature_derivative, 1e-5);
    EXPECT_NEAR(p.position.z(), 1.0, 1e-12);
  }
}

TEST(OffsetCurve, LoopLengthCountsTheBackwardStretch) {
  // a = 0.5: radius of curvature 1 at the vertex, offset 2 on the concave side: the offset runs
  // backwards where kappa > 1/2, i.e. |x| < x_c with (1 + x^2)^(3/2) = 2.
  test::ParabolaCurve parabola(0.5, -4.0, 4.0);
  auto base = std::make_shared<test::ParabolaCurve>(parabola);
  const double d = 2.0;
  const double xc = std::sqrt(std::pow(2.0, 2.0 / 3.0) - 1.0);
  const double length_c = parabola.primitive(xc) - parabola.primitive(-xc);
  const double turning_c = 2 * parabola.angle_at_x(xc);
  const double turning = 2 * parabola.angle_at_x(4.0);
  const double expected = (parabola.length() - length_c - d * (turning - turning_c)) + (d * turning_c - length_c);
  OffsetCurve off(base, d, kZ);
  EXPECT_LT(std::abs(off.length() - expected) / expected, 1e-6);
}

TEST(OffsetCurve, TrimmedStretchStartsAtTheBaseParameter) {
  auto arc = std::make_shared<ArcCurve>(Vec3(0, 0, 0), 10.0, Plane::G17, 0.0, kPi, 0.0);
  OffsetCurve off(arc, -1.0, kZ, 10.0 * kPi / 4, 10.0 * kPi / 2);  // 45..90 degrees, radius 11
  EXPECT_NEAR(off.length(), 11.0 * kPi / 4, 1e-8);
  EXPECT_TRUE(off.start().isApprox(Vec3(11 / std::sqrt(2.0), 11 / std::sqrt(2.0), 0), 1e-9));
  EXPECT_TRUE(off.end().isApprox(Vec3(0, 11, 0), 1e-9));
}

TEST(OffsetCurve, NormalRampShiftsAlongTheNormalLinearlyInTheBaseParameter) {
  // The offset of a quarter circle of radius 10 by -1 (radius 11), shifted by 0.5 mm at its start
  // and -1.5 mm at its end: a helix of radius 11 about the axis, Z = 0.5 - 2 * (angle / 90 deg),
  // length sqrt((11 pi / 2)^2 + 2^2).
  auto arc = std::make_shared<ArcCurve>(Vec3(0, 0, 0), 10.0, Plane::G17, 0.0, kPi / 2, 0.0);
  OffsetCurve off(arc, -1.0, kZ, 0.0, arc->length(), NormalRamp{0.5, -1.5});
  EXPECT_NEAR(off.length(), std::hypot(11.0 * kPi / 2, 2.0), 1e-7);
  for (int i = 0; i <= 8; ++i) {
    const CurvePoint p = off.at(off.length() * i / 8);
    const double angle = std::atan2(p.position.y(), p.position.x());
    EXPECT_NEAR(std::hypot(p.position.x(), p.position.y()), 11.0, 1e-9);
    EXPECT_NEAR(p.position.z(), 0.5 - 2.0 * angle / (kPi / 2), 1e-7);
    // A helix's curvature: r / (r^2 + c^2) with c = -2 mm per pi/2 rad.
    const double c = 2.0 / (kPi / 2);
    EXPECT_NEAR(p.curvature, 11.0 / (121.0 + c * c), 1e-6);
  }
}

}  // namespace
}  // namespace drycut::geometry
