// Sampled pieces of curves without a closed form (element_discretisation.hpp steps 4-6): a
// steep monotone flank of the velocity bound is accepted where a ramp could not follow it (step
// 6), the bottom of a dip stays resolved, and every piece's cap is checked against dense samples
// of the same synthetic bound and the closed-form ramp reach.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "interp/geometry/polynomial_span.hpp"
#include "motion/element_discretisation.hpp"
#include "motion/velocity_ramp.hpp"
#include "test_curves.hpp"

namespace drycut::motion::testing {
namespace {

constexpr double kFeed = 25.0;     // mm/s
constexpr double kLength = 0.16;   // mm, a BSPLINE span over short control legs
constexpr double kDip = 0.02;      // mm, where the bound is lowest
constexpr double kWidth = 0.008;   // mm
constexpr RampLimits kRamp{5000.0, 20000.0};

constexpr double kJerk = 1e5;      // mm/s³, of the synthetic curvature-rate bound

// The jerk bound of a BSPLINE span over short control legs, v = cbrt(j / |d3P/ds3|): it rises
// from below the feed and dips by 10 % near kDip on the way.
double jerk_bound(double s) { return 24.2 + 60.0 * s - 2.4 * std::exp(-std::pow((s - kDip) / kWidth, 2)); }
double bound_at(double s) { return std::min(kFeed, jerk_bound(s)); }

// A straight line along X that carries that curvature rate (the discretiser's worst point takes
// per-axis maxima of |t_i|, |κ_i|, |d3P_i/ds3|, so the bound must come from them).
class DipCurve : public geometry::Curve {
 public:
  double length() const override { return kLength; }
  CurvePoint at(double s) const override {
    CurvePoint p;
    p.position = Vec3(s, 0, 0);
    p.tangent = Vec3::UnitX();
    p.curvature_rate = Vec3(kJerk / std::pow(jerk_bound(s), 3), 0, 0);
    return p;
  }
  double max_curvature() const override { return 0; }
};

struct DipLimits {
  LocalLimits operator()(const CurvePoint& p) const {
    LocalLimits limits;
    limits.bound.velocity = std::min(kFeed, std::cbrt(kJerk / std::abs(p.curvature_rate.x())));
    limits.ramp = kRamp;
    return limits;
  }
};

std::vector<Station> discretise(double reach_tolerance) {
  DiscretisationRule rule;
  rule.sampled_reach_tolerance = reach_tolerance;
  std::vector<Station> out;
  EXPECT_TRUE(discretise_element(DipCurve{}, kLength, 0.01, rule, DipLimits{}, out));
  return out;
}

double dense_min(double a, double b) {
  double v = INFINITY;
  for (int k = 0; k <= 4000; ++k) v = std::min(v, bound_at(a + (b - a) * k / 4000));
  return v;
}

TEST(SampledDiscretisation, FlanksARampCannotFollowAreNotHalvedToTheMinimumPiece) {
  const auto halved = discretise(0.0);  // the rule without step 6
  const auto sampled = discretise(1e-4);
  EXPECT_GT(halved.size(), 20u);
  EXPECT_LT(sampled.size() * 3, halved.size() * 2);  // 15 against 27
}

TEST(SampledDiscretisation, EveryPieceIsCappedAtItsDenseMinimumOrWithinTheTolerance) {
  const auto stations = discretise(1e-4);
  ASSERT_GE(stations.size(), 2u);
  EXPECT_EQ(stations.front().s, 0.0);
  EXPECT_EQ(stations.back().s, kLength);
  for (size_t k = 1; k < stations.size(); ++k) {
    const double a = stations[k - 1].s, b = stations[k].s, cap = stations[k].piece_bound.velocity;
    const double lowest = dense_min(a, b);
    // A piece is either flat within the sampled tolerance (0.2 %) or one a ramp from its cap
    // cannot leave by more than 1e-4 (exact SOFT reach, the rule uses an upper bound of it).
    const double reach = ramp_reach(cap, b - a, kRamp);
    const bool flat = cap >= std::max(bound_at(a), bound_at(b)) * (1 - 0.002);
    EXPECT_TRUE(flat || reach <= cap * (1 + 1e-4)) << "piece " << a << " .. " << b;
    // The cap never exceeds the bound inside the piece by more than the flat tolerance.
    EXPECT_LE(cap, lowest * (1 + 0.002)) << "piece " << a << " .. " << b;
  }
}

TEST(SampledDiscretisation, TheBottomOfTheDipKeepsItsValue) {
  // The dip's bottom piece is not monotone and is halved until flat within 0.2 %, as before.
  const auto stations = discretise(1e-4);
  double lowest_cap = INFINITY;
  for (size_t k = 1; k < stations.size(); ++k) lowest_cap = std::min(lowest_cap, stations[k].piece_bound.velocity);
  const double bottom = dense_min(0.0, kLength);
  EXPECT_GE(lowest_cap, bottom * (1 - 1e-12));
  EXPECT_LE(lowest_cap, bottom * (1 + 0.002));
  const auto halved = discretise(0.0);
  double lowest_halved = INFINITY;
  for (size_t k = 1; k < halved.size(); ++k) lowest_halved = std::min(lowest_halved, halved[k].piece_bound.velocity);
  EXPECT_EQ(lowest_cap, lowest_halved);
}

// A spline span is halved at parameter midpoints whose arc length is a Gauss integral from the
// piece's start (step 4): every station must still lie where the span's own arc-length
// inversion puts its s, for a span whose parameter speed varies (a Hermite span with unequal
// end tangents) and for a rational one.
TEST(SampledDiscretisation, SplineSpanStationsLieAtTheirArcLength) {
  Eigen::Matrix4d rational = Eigen::Matrix4d::Zero();
  rational.col(0) << 0.0, 0.0, 0.0, 1.0;  // H = (w·x, w·y, w·z, w), w = 1 + u², a bent curve
  rational.col(1) << 0.3, 0.1, 0.0, 0.0;
  rational.col(2) << 0.0, 0.4, 0.0, 1.0;
  rational.col(3) << 0.1, 0.0, 0.05, 0.0;
  const geometry::PolynomialSpan spans[] = {
      geometry::PolynomialSpan::hermite(Vec3(0, 0, 0), Vec3(0.4, 0.2, 0), Vec3(0.1, 0.9, 0), Vec3(1.5, -0.8, 0.1),
                                        1.0),
      geometry::PolynomialSpan(rational, 1.0)};
  // A bound falling with the curvature (as the curvature constraint's sqrt(a/κ)).
  auto limits = [](const CurvePoint& p) {
    LocalLimits l;
    l.bound.velocity = std::min(kFeed, std::sqrt(500.0 / std::max(p.curvature, 1e-9)));
    l.ramp = kRamp;
    return l;
  };
  for (const auto& span : spans) {
    std::vector<Station> out;
    ASSERT_TRUE(discretise_element(span, span.length(), 0.01, DiscretisationRule{}, limits, out));
    ASSERT_GT(out.size(), 4u);
    EXPECT_EQ(out.front().s, 0.0);
    EXPECT_EQ(out.back().s, span.length());
    for (size_t k = 1; k < out.size(); ++k) {
      EXPECT_GT(out[k].s, out[k - 1].s);
      EXPECT_LT((out[k].point.position - span.at(out[k].s).position).norm(), 1e-10) << "station " << k;
      EXPECT_LT((out[k].point.tangent - span.at(out[k].s).tangent).norm(), 1e-9) << "station " << k;
    }
  }
}

}  // namespace
}  // namespace drycut::motion::testing
