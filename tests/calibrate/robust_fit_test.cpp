// The solver against closed forms: an exponential decay with known parameters, with and without
// an outlier; the bound transform.
#include "calibrate/robust_fit.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace drycut::calibrate {
namespace {

TEST(BoundTransform, RoundTripsAndStaysInside) {
  const Bounds b{0.5, 200};
  for (double v : {0.5001, 1.0, 7.3, 199.9}) EXPECT_NEAR(from_unbounded(to_unbounded(v, b), b), v, 1e-9 * v);
  EXPECT_GE(from_unbounded(-60, b), b.lower);
  EXPECT_LE(from_unbounded(60, b), b.upper);
  // The middle of the log range is the geometric mean of the bounds.
  EXPECT_NEAR(from_unbounded(0.0, b), std::sqrt(0.5 * 200), 1e-9);
}

TEST(HuberCost, QuadraticInsideLinearOutside) {
  Eigen::VectorXd r(2);
  r << 0.02, -0.3;
  // 0.02²/2 + (0.05·0.3 - 0.05²/2)
  EXPECT_NEAR(huber_cost(r, 0.05), 0.0002 + 0.015 - 0.00125, 1e-15);
}

// y = a·exp(-b·x) sampled at 10 points; residuals relative to y.
struct Decay {
  std::vector<double> x, y;
  Decay(double a, double b) {
    for (int i = 0; i < 10; ++i) {
      x.push_back(0.3 * i);
      y.push_back(a * std::exp(-b * 0.3 * i));
    }
  }
  ResidualFunction residuals() const {
    return [this](const std::vector<double>& p) {
      Eigen::VectorXd r(x.size());
      for (size_t i = 0; i < x.size(); ++i) r[i] = (p[0] * std::exp(-p[1] * x[i]) - y[i]) / y[i];
      return r;
    };
  }
};

TEST(RobustFit, RecoversExactParameters) {
  const Decay d(2.0, 0.5);
  const auto fit = robust_fit(d.residuals(), {{0.1, 10}, {0.01, 5}}, {{1.0, 1.0}, {5.0, 0.05}});
  EXPECT_NEAR(fit.values[0], 2.0, 2e-4);
  EXPECT_NEAR(fit.values[1], 0.5, 1e-4);
  EXPECT_LT(fit.cost, 1e-8);
}

TEST(RobustFit, HuberWeightsKeepAnOutlierFromPullingTheFit) {
  Decay d(2.0, 0.5);
  d.y[4] *= 1.5;  // one reading 50 % off
  RobustFitOptions robust;
  const auto fit = robust_fit(d.residuals(), {{0.1, 10}, {0.01, 5}}, {{1.0, 1.0}}, robust);
  RobustFitOptions plain;
  plain.huber_k = 1e9;  // every weight 1: ordinary least squares
  const auto ls = robust_fit(d.residuals(), {{0.1, 10}, {0.01, 5}}, {{1.0, 1.0}}, plain);
  const double robust_error = std::abs(fit.values[1] - 0.5);
  const double ls_error = std::abs(ls.values[1] - 0.5);
  EXPECT_LT(robust_error, 0.5 * ls_error);
  EXPECT_LT(fit.weights[4], 0.2);  // the outlier is weighted down (k / |r| with |r| near 1/3)
}

TEST(RobustFit, ABoundedOptimumStopsAtTheBound) {
  // The best b is 0.5, the upper bound 0.3: the fit ends at the bound, not beyond it.
  const Decay d(2.0, 0.5);
  const auto fit = robust_fit(d.residuals(), {{0.1, 10}, {0.01, 0.3}}, {{1.0, 0.1}});
  EXPECT_LE(fit.values[1], 0.3);
  EXPECT_GT(fit.values[1], 0.29);
}

TEST(RobustFit, SameInputSameOutput) {
  Decay d(2.0, 0.5);
  d.y[2] *= 1.2;
  const auto a = robust_fit(d.residuals(), {{0.1, 10}, {0.01, 5}}, {{1.0, 1.0}, {0.3, 3.0}});
  const auto b = robust_fit(d.residuals(), {{0.1, 10}, {0.01, 5}}, {{1.0, 1.0}, {0.3, 3.0}});
  EXPECT_EQ(a.values, b.values);
  EXPECT_EQ(a.start_index, b.start_index);
}

}  // namespace
}  // namespace drycut::calibrate
