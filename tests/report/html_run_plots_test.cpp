#include "report/html_run_plots.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "report_test_support.hpp"

namespace drycut::report {
namespace {

using geometry::Vec3;
using namespace drycut::report::test;

TEST(RunPlotCollector, ProgrammedPathKnotsAndLength) {
  RunPlotCollector c;
  c.on_programmed(line({0, 0, 0}, {10, 0, 0}, 1000, 10));
  c.on_programmed(line({10, 0, 0}, {10, 5, 0}, 0, 20, true));
  c.on_programmed(line({10, 5, 0}, {0, 5, 0}, 500, 30));
  const RunPlots p = c.plots();
  EXPECT_DOUBLE_EQ(p.programmed_length_mm, 25.0);
  ASSERT_EQ(p.knot_count, 2u);  // rapids are not knots
  EXPECT_DOUBLE_EQ(p.knots[0].x, 10.0);
  EXPECT_DOUBLE_EQ(p.knots[1].x, 0.0);
  EXPECT_DOUBLE_EQ(p.knots[1].y, 5.0);
  ASSERT_FALSE(p.programmed_path.empty());
  EXPECT_DOUBLE_EQ(p.programmed_path.front().x, 0.0);
  EXPECT_DOUBLE_EQ(p.programmed_path.back().x, 0.0);
  EXPECT_DOUBLE_EQ(p.programmed_path.back().s, 25.0);
  EXPECT_FALSE(p.has_deviation);
}

TEST(RunPlotCollector, FeedStepsFollowTheTimedBlocksWithGapsForRapids) {
  RunPlotCollector c;
  const auto a = line({0, 0, 0}, {10, 0, 0}, 1200, 10);
  const auto r = line({10, 0, 0}, {10, 5, 0}, 0, 20, true);
  const auto b = line({10, 5, 0}, {0, 5, 0}, 600, 30);
  for (const auto* e : {&a, &r, &b}) c.on_tool_centre(*e);
  c.on_block(timing(a, 1.0, 20));
  c.on_block(timing(r, 0.5, 0));
  c.on_block(timing(b, 2.0, 10));
  const auto f = c.plots().feed;
  // F = 20 mm/s over t 0..1 (s 0..10), a break, F = 10 mm/s over t 1.5..3.5 (s 15..25).
  ASSERT_EQ(f.size(), 5u);
  EXPECT_DOUBLE_EQ(f[0].t, 0.0);
  EXPECT_DOUBLE_EQ(f[0].v, 20.0);
  EXPECT_DOUBLE_EQ(f[1].t, 1.0);
  EXPECT_DOUBLE_EQ(f[1].s, 10.0);
  EXPECT_TRUE(std::isnan(f[2].v));
  EXPECT_DOUBLE_EQ(f[3].t, 1.5);
  EXPECT_DOUBLE_EQ(f[3].s, 15.0);
  EXPECT_DOUBLE_EQ(f[3].v, 10.0);
  EXPECT_DOUBLE_EQ(f[4].t, 3.5);
  EXPECT_DOUBLE_EQ(f[4].s, 25.0);
}

TEST(RunPlotCollector, ConsecutiveBlocksWithOneFeedMakeOneRun) {
  RunPlotCollector c;
  const auto a = line({0, 0, 0}, {10, 0, 0}, 600, 10);
  const auto b = line({10, 0, 0}, {20, 0, 0}, 600, 11);
  c.on_tool_centre(a);
  c.on_tool_centre(b);
  c.on_block(timing(a, 1.0, 10));
  c.on_block(timing(b, 1.0, 10));
  const auto f = c.plots().feed;
  ASSERT_EQ(f.size(), 2u);
  EXPECT_DOUBLE_EQ(f[1].t, 2.0);
  EXPECT_DOUBLE_EQ(f[1].s, 20.0);
}

TEST(RunPlotCollector, SampleArcLengthIsTheChordSum) {
  RunPlotCollector c;
  const BlockRef src = block(10);
  c.on_sample(sample(0.000, 0, 0, 1, &src));
  c.on_sample(sample(0.004, 3, 0, 1, &src));
  c.on_sample(sample(0.008, 3, 4, 1, &src));
  const auto p = c.plots();
  ASSERT_EQ(p.tool_path.size(), 3u);
  EXPECT_DOUBLE_EQ(p.tool_path[1].s, 3.0);
  EXPECT_DOUBLE_EQ(p.tool_path[2].s, 7.0);
  EXPECT_EQ(p.samples, 3u);
}

TEST(RunPlotCollector, LocatesADipAtItsSlowestSample) {
  RunPlotCollector c;
  const auto a = line({0, 0, 0}, {10, 0, 0}, 600, 30);  // F = 10 mm/s
  c.on_tool_centre(a);
  c.on_sample(sample(0.1, 1, 0, 8, &a.source));
  c.on_sample(sample(0.2, 5, 0, 2, &a.source));
  c.on_sample(sample(0.3, 9, 0, 9, &a.source));
  c.on_block(timing(a, 1.0, 2.0, motion::Limit::Curvature));
  motion::FeedDip dip;
  dip.min_element = a.source;
  dip.min_source = block(98);  // a block inside a compressed span: the element is what is found
  dip.v_min_mm_s = 2.0;
  const DipLocation at = c.locate(dip);
  ASSERT_TRUE(at.known);
  EXPECT_DOUBLE_EQ(at.x, 5.0);
  EXPECT_DOUBLE_EQ(at.t, 0.2);
  dip.min_element = block(99);
  EXPECT_FALSE(c.locate(dip).known);
}

TEST(RunPlotCollector, ExactStopsAreNotDips) {
  RunPlotCollector c;
  const auto a = line({0, 0, 0}, {10, 0, 0}, 600, 30);
  c.on_tool_centre(a);
  c.on_block(timing(a, 1.0, 0.0, motion::Limit::ExactStop));
  motion::FeedDip dip;
  dip.min_element = a.source;
  EXPECT_FALSE(c.locate(dip).known);
}

TEST(RunPlotCollector, DeviationOnlyForBlocksOnTheContour) {
  RunPlotOptions o;
  o.distance_to_reference = [](double, double y) { return std::abs(y); };  // reference: the X axis
  RunPlotCollector c(o);
  c.on_programmed(line({0, 0, 0}, {10, 0.01, 0}, 600, 10));  // ends 0 and 0.01 from the axis: on it
  c.on_programmed(line({10, 0.01, 0}, {10, 5, 0}, 600, 20)); // leaves the contour: no deviation
  const RunPlots p = c.plots();
  ASSERT_TRUE(p.has_deviation);
  EXPECT_NEAR(p.max_deviation_mm, 0.01, 1e-12);  // the largest |y| on the first line, at its end
  bool gap = false;
  for (const auto& q : p.programmed_path) gap = gap || std::isnan(q.value);
  EXPECT_TRUE(gap);
}

}  // namespace
}  // namespace drycut::report
