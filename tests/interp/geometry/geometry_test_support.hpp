#pragma once
// Helpers shared by the geometry tests: running a spline builder, finite differences along a
// curve, and reference measurements that do not use the code under test.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <functional>
#include <vector>

#include "interp/geometry/curve.hpp"
#include "interp/geometry/spline_builder.hpp"

namespace drycut::geometry::testing {

// Feeds all points (pop_span after every point, as the interpreter would) and finishes.
inline std::vector<SplineSpan> run_spline(SplineBuilder& builder, const std::vector<Vec3>& points,
                                          const SplineEnd& end = {}, const std::vector<double>& weights = {},
                                          const std::vector<double>& pls = {}) {
  std::vector<SplineSpan> spans;
  SplineSpan span;
  for (size_t i = 0; i < points.size(); ++i) {
    builder.add_point(points[i], weights.empty() ? 1.0 : weights[i], pls.empty() ? 0.0 : pls[i]);
    while (builder.pop_span(span)) spans.push_back(span);
  }
  builder.finish(end);
  while (builder.pop_span(span)) spans.push_back(span);
  return spans;
}

// Length of the polyline through f(u) at n+1 equal steps of u in [a, b]: an independent
// arc-length reference for a parametric curve (error ~ L (kappa h)^2 / 24).
inline double polyline_length(const std::function<Vec3(double)>& f, double a, double b, int n) {
  double len = 0.0;
  Vec3 prev = f(a);
  for (int i = 1; i <= n; ++i) {
    const Vec3 p = f(a + (b - a) * i / n);
    len += (p - prev).norm();
    prev = p;
  }
  return len;
}

// Central differences of position, tangent and curvature vector at arc length s must match the
// reported derivatives; d2P/ds2 must be perpendicular to the unit tangent.
inline void expect_consistent_derivatives(const Curve& c, double s, double tol = 1e-5) {
  const double h = 1e-4 * std::max(1.0, c.length());
  ASSERT_GT(s - h, 0.0);
  ASSERT_LT(s + h, c.length());
  const CurvePoint p = c.at(s), a = c.at(s - h), b = c.at(s + h);
  EXPECT_NEAR(p.tangent.norm(), 1.0, 1e-12);
  EXPECT_NEAR(p.curvature_vector.dot(p.tangent), 0.0, 1e-9 * std::max(1.0, p.curvature));
  const Vec3 t_fd = (b.position - a.position) / (2 * h);
  const Vec3 k_fd = (b.tangent - a.tangent) / (2 * h);
  const Vec3 r_fd = (b.curvature_vector - a.curvature_vector) / (2 * h);
  const double kd_fd = (b.curvature - a.curvature) / (2 * h);
  EXPECT_LT((t_fd - p.tangent).norm(), tol) << "s=" << s;
  EXPECT_LT((k_fd - p.curvature_vector).norm(), tol * std::max(1.0, p.curvature)) << "s=" << s;
  EXPECT_LT((r_fd - p.curvature_rate).norm(), 10 * tol * std::max(1.0, p.curvature_rate.norm())) << "s=" << s;
  EXPECT_NEAR(kd_fd, p.curvature_derivative, 10 * tol * std::max(1.0, std::abs(p.curvature_derivative)));
  EXPECT_NEAR(p.curvature, p.curvature_vector.norm(), 1e-12);
}

}  // namespace drycut::geometry::testing
