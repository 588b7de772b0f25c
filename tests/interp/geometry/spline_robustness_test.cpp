// Awkward inputs must give finite curves or an alarm, never a crash, NaN or hang.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "geometry_test_support.hpp"
#include "interp/geometry/arc_solvers.hpp"
#include "interp/geometry/spline_builder.hpp"

namespace drycut::geometry {
namespace {

void expect_finite(const Curve& c) {
  ASSERT_TRUE(std::isfinite(c.length()));
  for (double f : {0.0, 0.37, 1.0}) {
    const CurvePoint p = c.at(f * c.length());
    EXPECT_TRUE(p.position.allFinite());
    EXPECT_TRUE(p.tangent.allFinite());
    EXPECT_NEAR(p.tangent.norm(), 1.0, 1e-9);
  }
  EXPECT_TRUE(std::isfinite(c.max_curvature()));
}

TEST(SplineRobustness, RandomRunsWithRepeatsCollinearStretchesAndHugeJumps) {
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 60; ++trial) {
    std::vector<Vec3> pts;
    const int n = 1 + trial % 13;
    for (int i = 0; i < n; ++i) {
      const int kind = static_cast<int>(rng() % 5);
      if (kind == 0 && !pts.empty()) pts.push_back(pts.back());                               // repeat
      else if (kind == 1 && pts.size() >= 2) pts.push_back(2 * pts.back() - pts[pts.size() - 2]);  // collinear
      else if (kind == 2) pts.emplace_back(1e4 * u(rng), 1e4 * u(rng), 0);                     // jump
      else pts.emplace_back(u(rng), u(rng), 0.01 * u(rng));
    }
    const SplineEnd ends[] = {{EndCondition::Natural, {}}, {EndCondition::Tangent, Vec3(0, 1, 0)},
                              {EndCondition::Auto, {}}, {EndCondition::Tangent, Vec3::Zero()}};
    for (const SplineEnd& e : ends) {
      std::vector<std::unique_ptr<SplineBuilder>> builders;
      builders.push_back(make_akima_builder(e));
      builders.push_back(make_cubic_builder(e, 0));
      builders.push_back(make_cubic_builder(e, 8));
      builders.push_back(make_cubic_builder(e, 1));
      builders.push_back(make_nurbs_builder(2 + trial % 2));
      for (auto& b : builders) {
        // A block owns at most one span (SplineRun moves the block's element into it): the
        // block indices of consecutive spans strictly increase, within the run's blocks.
        size_t previous = 0;
        for (const auto& s : testing::run_spline(*b, pts, e)) {
          expect_finite(*s.curve);
          EXPECT_GT(s.block_index, previous);
          EXPECT_LT(s.block_index, pts.size());
          previous = s.block_index;
        }
      }
    }
  }
}

TEST(ArcRobustness, RandomArcInputsGiveACurveOrAnAlarm) {
  std::mt19937 rng(777);
  std::uniform_real_distribution<double> u(-10.0, 10.0);
  auto v = [&] { return Vec3(u(rng), u(rng), u(rng)); };
  for (int i = 0; i < 2000; ++i) {
    const Plane plane = static_cast<Plane>(i % 3);
    const bool cw = i % 2 == 0;
    const ArcResult results[] = {
        arc_from_center(v(), v(), v(), cw, plane, i % 3, {}),
        arc_from_radius(v(), v(), u(rng), cw, plane),
        arc_from_angle_and_center(v(), v(), v(), u(rng), cw, plane, i % 2),
        arc_from_angle_and_end(v(), v(), u(rng), cw, plane),
        arc_through_point(v(), v(), v()),
        arc_tangent(v(), v(), v(), plane),
    };
    for (const ArcResult& r : results) {
      if (r.ok()) {
        ASSERT_NE(r.curve, nullptr);
        expect_finite(*r.curve);
      } else {
        EXPECT_EQ(r.curve, nullptr);
        EXPECT_FALSE(r.detail.empty());
      }
    }
  }
}

}  // namespace
}  // namespace drycut::geometry
