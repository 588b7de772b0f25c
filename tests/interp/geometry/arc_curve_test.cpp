#include "interp/geometry/arc_curve.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "geometry_test_support.hpp"

namespace drycut::geometry {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(ArcCurve, QuarterCircleClosedForms) {
  const ArcCurve arc(Vec3(0, 0, 0), 10.0, Plane::G17, 0.0, kPi / 2, 0.0);
  EXPECT_NEAR(arc.length(), 5 * kPi, 1e-12);
  EXPECT_NEAR(arc.max_curvature(), 0.1, 1e-15);
  EXPECT_LT((arc.end() - Vec3(0, 10, 0)).norm(), 1e-12);
  const CurvePoint mid = arc.at(2.5 * kPi);
  const double r2 = 10 / std::sqrt(2.0);
  EXPECT_LT((mid.position - Vec3(r2, r2, 0)).norm(), 1e-12);
  EXPECT_LT((mid.tangent - Vec3(-1, 1, 0).normalized()).norm(), 1e-12);
  // Curvature vector points to the centre with magnitude 1/r.
  EXPECT_LT((mid.curvature_vector - Vec3(-r2, -r2, 0) / 100.0).norm(), 1e-12);
}

TEST(ArcCurve, ClockwiseSweepRunsTheOtherWay) {
  const ArcCurve arc(Vec3(0, 0, 0), 10.0, Plane::G17, 0.0, -kPi / 2, 0.0);
  EXPECT_LT((arc.end() - Vec3(0, -10, 0)).norm(), 1e-12);
  EXPECT_LT((arc.at(0).tangent - Vec3(0, -1, 0)).norm(), 1e-12);
}

TEST(ArcCurve, HelixLengthAndCurvature) {
  // r = 5, two turns, 8 mm rise: c = 8 / (4 pi) mm/rad; kappa = r / (r^2 + c^2).
  const double r = 5, sweep = 4 * kPi, h = 8;
  const ArcCurve helix(Vec3(1, 1, 0), r, Plane::G17, 0.0, sweep, h);
  const double c = h / sweep;
  EXPECT_NEAR(helix.length(), std::sqrt(r * sweep * r * sweep + h * h), 1e-12);
  EXPECT_NEAR(helix.max_curvature(), r / (r * r + c * c), 1e-15);
  EXPECT_NEAR(helix.at(3.0).curvature, r / (r * r + c * c), 1e-15);
  EXPECT_LT((helix.end() - Vec3(6, 1, 8)).norm(), 1e-12);
  // Independent length reference: fine polyline of the helix formula.
  const double poly = testing::polyline_length(
      [&](double t) { return Vec3(1 + r * std::cos(t), 1 + r * std::sin(t), h * t / sweep); }, 0, sweep, 200000);
  EXPECT_NEAR(helix.length() / poly, 1.0, 1e-8);
  testing::expect_consistent_derivatives(helix, 10.0);
  testing::expect_consistent_derivatives(helix, helix.length() * 0.77);
}

TEST(ArcCurve, PlanesG18AndG19AreRightHanded) {
  // G18: plane axes (Z, X), positive angle turns Z towards X about +Y.
  const ArcCurve g18(Vec3::Zero(), 1.0, Plane::G18, 0.0, kPi / 2, 0.0);
  EXPECT_LT((g18.start() - Vec3(0, 0, 1)).norm(), 1e-15);
  EXPECT_LT((g18.end() - Vec3(1, 0, 0)).norm(), 1e-12);
  EXPECT_LT((g18.normal() - Vec3(0, 1, 0)).norm(), 1e-15);
  // G19: plane axes (Y, Z), positive angle turns Y towards Z about +X.
  const ArcCurve g19(Vec3::Zero(), 1.0, Plane::G19, 0.0, kPi / 2, 2.0);
  EXPECT_LT((g19.start() - Vec3(0, 1, 0)).norm(), 1e-15);
  EXPECT_LT((g19.end() - Vec3(2, 0, 1)).norm(), 1e-12);
}

TEST(ArcCurve, DerivativesMatchFiniteDifferencesInAnyPlane) {
  const ArcCurve arc(Vec3(3, -2, 1), 7.0, Vec3(1, 0, 0), Vec3(0, std::cos(0.3), std::sin(0.3)), 0.4, -2.5, -3.0);
  for (double f : {0.1, 0.5, 0.9}) testing::expect_consistent_derivatives(arc, f * arc.length());
}

}  // namespace
}  // namespace drycut::geometry
