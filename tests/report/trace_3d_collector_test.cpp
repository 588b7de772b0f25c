// The 3D trace: samples in 3D with their block, rapids flagged, bounded output, and the block
// of every kept sample still known after a long run (the block store is pruned).
#include "report/trace_3d_collector.hpp"

#include <gtest/gtest.h>

#include <string>

#include "report_test_support.hpp"

namespace drycut::report {
namespace {

using namespace drycut::report::test;

motion::TrajectorySample sample3(double t, double x, double y, double z, double v, const BlockRef* source) {
  motion::TrajectorySample s = sample(t, x, y, v, source);
  s.position.z() = z;
  return s;
}

TEST(Trace3dCollector, SamplesCarryTheirBlockAndRapidFlag) {
  Trace3dCollector c;
  const auto r = line({0, 0, 50}, {10, 0, 5}, 0, 1, true);
  const auto a = line({10, 0, 5}, {10, 10, 5}, 600, 2);
  c.on_tool_centre(r);
  c.on_tool_centre(a);
  // The planner: the rapid's samples, its timing, then the cut's samples and timing.
  const BlockRef rb = block(1, "N1 G0 X10 Z5"), ab = block(2, "N2 G1 Y10 F600");
  c.on_sample(sample3(0.0, 0, 0, 50, 0, &rb));
  c.on_sample(sample3(0.1, 5, 0, 27.5, 500, &rb));
  c.on_block(timing(r, 0.2, 0));
  c.on_sample(sample3(0.2, 10, 0, 5, 0, &ab));
  c.on_sample(sample3(0.3, 10, 5, 5, 10, &ab));
  c.on_block(timing(a, 1.0, 0));
  const Trace3d tr = c.trace();
  ASSERT_EQ(tr.points.size(), 4u);
  ASSERT_EQ(tr.blocks.size(), 2u);
  EXPECT_EQ(tr.samples, 4u);
  EXPECT_DOUBLE_EQ(tr.points[1].z, 27.5);
  EXPECT_TRUE(tr.points[0].rapid && tr.points[1].rapid);
  EXPECT_FALSE(tr.points[2].rapid || tr.points[3].rapid);
  EXPECT_EQ(tr.points[1].block, 0u);
  EXPECT_EQ(tr.points[2].block, 1u);
  EXPECT_EQ(tr.blocks[0].text, "N1 G0 X10 Z5");
  EXPECT_TRUE(tr.blocks[0].rapid);
  EXPECT_EQ(tr.blocks[1].line, 2u);
  EXPECT_DOUBLE_EQ(tr.blocks[1].feed_mm_s, 10.0);  // F600 mm/min
  EXPECT_EQ(*tr.blocks[1].file, "/tmp/TEST.MPF");
}

TEST(Trace3dCollector, LongRunStaysBoundedAndKeepsTheRightBlockPerSample) {
  // 60000 blocks of 5 samples each, 20 buckets: the output holds at most 42 points, and each
  // kept sample must still name the block it came from (its text encodes the sample's x).
  Trace3dCollector c(20);
  std::vector<interp::PathElement> elements;
  for (uint32_t b = 0; b < 60000; ++b) {
    const auto e = line({double(b), 0, 0}, {double(b + 1), 0, 0}, 600, b + 1);
    c.on_tool_centre(e);
    const BlockRef ref = block(b + 1, "N" + std::to_string(b + 1));
    for (int k = 0; k < 5; ++k) {
      // One sample in 7919 dips to 1 mm/s: the extremes the decimator keeps.
      const uint64_t n = 5ull * b + k;
      c.on_sample(sample3(n * 0.001, b + 0.2 * k, 0, 0, n % 7919 == 0 ? 1.0 : 10.0, &ref));
    }
    c.on_block(timing(e, 0.005, 10));
  }
  const Trace3d tr = c.trace();
  EXPECT_EQ(tr.samples, 300000u);
  ASSERT_LE(tr.points.size(), 42u);
  ASSERT_GE(tr.points.size(), 2u);
  for (const auto& p : tr.points) {
    ASSERT_LT(p.block, tr.blocks.size());
    const uint32_t expected_line = static_cast<uint32_t>(p.x) + 1;  // block b spans x in [b, b + 0.8]
    EXPECT_EQ(tr.blocks[p.block].line, expected_line);
    EXPECT_EQ(tr.blocks[p.block].text, "N" + std::to_string(expected_line));
  }
  EXPECT_DOUBLE_EQ(tr.points.front().x, 0.0);  // first and last samples always kept
  EXPECT_DOUBLE_EQ(tr.points.back().x, 59999.8);
}

}  // namespace
}  // namespace drycut::report
