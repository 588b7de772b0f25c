// POLY polynomial interpolation and its curve. Every expected value is worked out beside it
// (docs/controller-state.md "Polynomial interpolation").
#include <cmath>
#include <numbers>
#include <string>

#include "interp/geometry/polynomial_curve.hpp"
#include "interp_test_support.hpp"

namespace drycut::interp::testing {
namespace {

// Length of y = x^2/10 - x over x in 0..10: 5 * (sqrt(2) + asinh(1)).
const double kParabolaLength = 5.0 * (std::sqrt(2.0) + std::asinh(1.0));

TEST(PolynomialCurve, ThroughStartAndEndWithHigherCoefficients) {
  // x = 10 p, y = -10 p + 10 p^2 on p in [0, 1]: the parabola above, from (0,0) to (10,0).
  Eigen::Matrix<double, 3, 4> higher = Eigen::Matrix<double, 3, 4>::Zero();
  higher(1, 0) = 10.0;
  const auto c = geometry::PolynomialCurve::through({0, 0, 0}, {10, 0, 0}, higher, 1.0);
  EXPECT_NEAR(c.length(), kParabolaLength, 1e-9);
  EXPECT_NEAR((c.end() - Eigen::Vector3d(10, 0, 0)).norm(), 0.0, 1e-12);
  // Halfway along the arc (by symmetry x = 5): y = 2.5 - 5 = -2.5, tangent along +X, curvature
  // y'' / (1 + y'^2)^1.5 = 0.2.
  const auto mid = c.at(c.length() / 2);
  EXPECT_NEAR(mid.position.x(), 5.0, 1e-7);
  EXPECT_NEAR(mid.position.y(), -2.5, 1e-7);
  EXPECT_NEAR(mid.tangent.x(), 1.0, 1e-7);
  EXPECT_NEAR(mid.curvature, 0.2, 1e-6);
  EXPECT_NEAR(c.max_curvature(), 0.2, 1e-9);
}

TEST(PolynomialCurve, QuinticTermAndParameterInterval) {
  // x = a1 p + a5 p^5 on p in [0, 2] with a5 = 0.1 and x(2) = 10: a1 = (10 - 3.2) / 2 = 3.4.
  // x is increasing (x' = 3.4 + 0.5 p^4 > 0): a straight path of length 10, x(1) = 3.5.
  Eigen::Matrix<double, 3, 4> higher = Eigen::Matrix<double, 3, 4>::Zero();
  higher(0, 3) = 0.1;
  const auto c = geometry::PolynomialCurve::through({0, 0, 0}, {10, 0, 0}, higher, 2.0);
  EXPECT_NEAR(c.length(), 10.0, 1e-9);
  EXPECT_NEAR(c.derivatives(1.0).p.x(), 3.5, 1e-12);
  EXPECT_NEAR(c.derivatives(1.0).d1.x(), 3.9, 1e-12);
  EXPECT_NEAR(c.derivatives(1.0).d2.x(), 2.0, 1e-12);
  EXPECT_NEAR(c.derivatives(1.0).d3.x(), 6.0, 1e-12);
}

TEST(Poly, BlockFollowsThePolynomialAtTheFeed) {
  // PO[X]=(10) PO[Y]=(0, 10) from (0, 0): the parabola; F600 = 10 mm/s along its length.
  auto r = run_program("G0 X0 Y0 Z0\nPOLY PO[X]=(10) PO[Y]=(0, 10) F600\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  auto m = r->sink.motions();
  ASSERT_EQ(m.size(), 2u);
  EXPECT_EQ(m[1].label, "POLY");
  EXPECT_NEAR(m[1].curve->length(), kParabolaLength, 1e-9);
  EXPECT_NEAR((m[1].curve->end() - Eigen::Vector3d(10, 0, 0)).norm(), 0.0, 1e-12);
  EXPECT_DOUBLE_EQ(m[1].feed_mm_s, 10.0);
}

TEST(Poly, PlainAxisWordsAndTheFrameTranslation) {
  // Under G54 (10, 20, 0): POLY X5 PO[Y]=(0, 4) PL=2: x = 2.5 p, y = -8 p + 4 p^2 (y(2) = 0),
  // i.e. y = 0.64 x^2 - 3.2 x: machine end (15, 20, 0); the middle p = 1 at x = 12.5, y = 16.
  auto r = run_program("G54 G0 X0 Y0 Z0\nPOLY X5 PO[Y]=(0, 4) PL=2 F600\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  auto m = r->sink.motions();
  ASSERT_EQ(m.size(), 2u);
  EXPECT_NEAR((m[1].curve->end() - Eigen::Vector3d(15, 20, 0)).norm(), 0.0, 1e-12);
  // Lowest point of the parabola: dy/dx = 0 at x = 2.5, y = 0.64 * 6.25 - 8 = -4: machine (12.5, 16).
  double lowest = 1e9;
  for (int i = 0; i <= 200; ++i) lowest = std::min(lowest, m[1].curve->at(m[1].curve->length() * i / 200).position.y());
  EXPECT_NEAR(lowest, 16.0, 1e-3);
}

TEST(Poly, DenominatorIsWarnedAndPlannedStraight) {
  auto r = run_program("G0 X0 Y0 Z0\nPOLY PO[X]=(10, 1) PO[]=(0.5) F600\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  auto m = r->sink.motions();
  ASSERT_EQ(m.size(), 2u);
  EXPECT_NEAR(m[1].curve->length(), 10.0, 1e-12);
  bool warned = false;
  for (const auto& a : r->diagnostics.items()) warned = warned || a.text.find("POLY denominator") != std::string::npos;
  EXPECT_TRUE(warned);
}

TEST(Poly, TooManyValuesIsASyntaxError) {
  auto r = run_program("POLY PO[X]=(10, 1, 2, 3, 4, 5) F600\nM30\n");
  ASSERT_TRUE(r->alarm);
  EXPECT_EQ(r->alarm->number, 12080);
}

}  // namespace
}  // namespace drycut::interp::testing
