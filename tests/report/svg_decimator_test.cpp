#include "report/svg_decimator.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace drycut::report {
namespace {

PlotPoint point(double t, double value) { return PlotPoint{t, 0, t, t, value, value}; }

TEST(PointDecimator, FewPointsPassUnchanged) {
  PointDecimator d(100);
  for (int i = 0; i < 50; ++i) d.add(point(i, std::sin(i)));
  const auto out = d.points();
  ASSERT_EQ(out.size(), 50u);
  for (int i = 0; i < 50; ++i) EXPECT_DOUBLE_EQ(out[static_cast<size_t>(i)].t, i);
}

TEST(PointDecimator, OutputStaysBoundedAndOrdered) {
  PointDecimator d(500);
  const int n = 1'000'000;
  for (int i = 0; i < n; ++i) d.add(point(i, std::sin(i * 0.001)));
  const auto out = d.points();
  EXPECT_LE(out.size(), 2u * 500u + 2u);
  EXPECT_GT(out.size(), 500u);  // not over-thinned
  EXPECT_EQ(d.count(), static_cast<uint64_t>(n));
  for (size_t i = 1; i < out.size(); ++i) EXPECT_LT(out[i - 1].t, out[i].t);
  EXPECT_DOUBLE_EQ(out.front().t, 0);      // first point kept
  EXPECT_DOUBLE_EQ(out.back().t, n - 1);   // last point kept
}

TEST(PointDecimator, ASingleSampleDipSurvives) {
  PointDecimator d(100);
  const int n = 200'000, dip_at = 123'457;
  for (int i = 0; i < n; ++i) d.add(point(i, i == dip_at ? 0.1 : 1.0));
  bool found = false;
  for (const auto& p : d.points()) found = found || (p.t == dip_at && p.value == 0.1);
  EXPECT_TRUE(found);
}

TEST(PointDecimator, BothExtremesOfAStretchSurvive) {
  PointDecimator d(10);
  for (int i = 0; i < 10'000; ++i) d.add(point(i, i == 5000 ? 9.0 : i == 7000 ? -9.0 : 0.0));
  int seen = 0;
  for (const auto& p : d.points()) seen += (p.value == 9.0) + (p.value == -9.0);
  EXPECT_EQ(seen, 2);
}

}  // namespace
}  // namespace drycut::report
