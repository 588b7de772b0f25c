#include "interp/geometry/line_curve.hpp"

#include <gtest/gtest.h>

namespace drycut::geometry {
namespace {

TEST(LineCurve, LengthPositionAndTangentFromEndPoints) {
  const LineCurve line(Vec3(1, 2, 3), Vec3(4, 6, 3));  // 3-4-5 triangle
  EXPECT_DOUBLE_EQ(line.length(), 5.0);
  const CurvePoint mid = line.at(2.5);
  EXPECT_NEAR((mid.position - Vec3(2.5, 4, 3)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((mid.tangent - Vec3(0.6, 0.8, 0)).norm(), 0.0, 1e-15);
  EXPECT_EQ(mid.curvature, 0.0);
  EXPECT_EQ(mid.curvature_vector, Vec3::Zero());
  EXPECT_EQ(line.max_curvature(), 0.0);
  EXPECT_EQ(line.at(5.0).position, Vec3(4, 6, 3));  // the end point exactly
  EXPECT_EQ(line.at(0.0).position, Vec3(1, 2, 3));
}

TEST(LineCurve, ClampsArcLength) {
  const LineCurve line(Vec3(0, 0, 0), Vec3(0, 0, -2));
  EXPECT_EQ(line.at(-1.0).position, Vec3(0, 0, 0));
  EXPECT_EQ(line.at(7.0).position, Vec3(0, 0, -2));
  EXPECT_EQ(line.at(1.0).tangent, Vec3(0, 0, -1));
}

TEST(LineCurve, ZeroLengthHasLengthZeroAndAUnitTangent) {
  const LineCurve line(Vec3(1, 1, 1), Vec3(1, 1, 1));
  EXPECT_EQ(line.length(), 0.0);
  const CurvePoint p = line.at(0.0);
  EXPECT_DOUBLE_EQ(p.tangent.norm(), 1.0);
  EXPECT_EQ(p.position, Vec3(1, 1, 1));
}

}  // namespace
}  // namespace drycut::geometry
