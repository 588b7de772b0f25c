// The compressor stage (block_compressor.hpp) on element streams from the real interpreter:
// which blocks join a run, what breaks it, the order of what passes, the flush window.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>

#include "interp/block_compressor.hpp"
#include "interp/cutter_compensation.hpp"
#include "interp_test_support.hpp"

namespace drycut::interp {
namespace {

using testing::CollectingSink;

// Runs NC text through interpreter -> BlockCompressor -> collector.
std::vector<PathElement> compressed(const std::string& text, const machine::MachineProfile& profile) {
  auto run = testing::run_program(text, profile);
  EXPECT_FALSE(run->alarm) << run->alarm->format();
  CollectingSink out;
  BlockCompressor stage(out, profile);
  for (auto& e : run->sink.elements) stage.consume(PathElement(e));
  stage.finish();
  EXPECT_TRUE(out.finished);
  return out.motions();
}

std::string x_blocks(int from, int to, const std::string& suffix = "") {
  std::string t;
  for (int i = from; i <= to; ++i) t += "G1 X" + std::to_string(i) + suffix + "\n";
  return t;
}

TEST(BlockCompressor, SimpleG1BlocksBecomeOneSpanLabelledWithTheCompressor) {
  const auto m = compressed("G0 X0 Y0 Z0\nG64 COMPCAD F3000\n" + x_blocks(1, 10) + "M30\n", testing::test_profile());
  ASSERT_EQ(m.size(), 2u);  // the G0, then one span
  EXPECT_EQ(m[1].kind, ElementKind::SplineSpan);
  EXPECT_EQ(m[1].label, "COMPCAD");
  EXPECT_EQ(m[1].compressed_blocks, 10u);
  EXPECT_EQ(m[1].source.line, 3u);  // its first block
  EXPECT_NEAR(m[1].curve->length(), 10.0, 1e-9);
}

TEST(BlockCompressor, CompofAndNonSimpleBlocksPassUnchanged) {
  const auto p = testing::test_profile();
  EXPECT_EQ(compressed("G0 X0 Y0 Z0\nG64 F3000\n" + x_blocks(1, 10) + "M30\n", p).size(), 11u);
  // G91 in a block, an M function alone between blocks, a T word: each ends the run.
  const auto m = compressed("G0 X0 Y0 Z0\nG64 COMPON F3000\n" + x_blocks(1, 3) + "G91 X1\nG90\n" + x_blocks(5, 7) +
                                "M8\n" + x_blocks(8, 10) + "M30\n",
                            p);
  std::vector<std::string> labels;
  for (const auto& e : m) labels.push_back(e.label);
  // G0, span X1..X3, the G91 line, (G90 alone ends the run), span X5..X7, span X8..X10.
  EXPECT_EQ(labels, (std::vector<std::string>{"G0", "COMPON", "G1", "COMPON", "COMPON"}));
  for (size_t i = 1; i < m.size(); ++i)
    EXPECT_LT((m[i].curve->start() - m[i - 1].curve->end()).norm(), 1e-12) << "the path stays connected at " << i;
}

// Ten X blocks under COMPCAD, each feed block edited as the compensation stage or a 5-axis post
// would change it (`edit(element, k)`, k = 0.. the feed block's index), through the compressor.
std::vector<PathElement> compressed_ten_blocks(const std::function<void(PathElement&, int)>& edit,
                                               const machine::MachineProfile& profile = testing::test_profile()) {
  auto run = testing::run_program("G0 X0 Y0 Z0\nG64 COMPCAD F3000\n" + x_blocks(1, 10) + "M30\n", profile);
  EXPECT_FALSE(run->alarm);
  CollectingSink out;
  BlockCompressor stage(out, profile);
  int k = 0;
  for (auto& e : run->sink.elements) {
    PathElement c(e);
    if (c.is_motion() && !c.rapid) edit(c, k++);
    stage.consume(std::move(c));
  }
  stage.finish();
  return out.motions();
}

TEST(BlockCompressor, CentreFeedRatiosOfCompensatedBlocksDoNotBreakTheRun) {
  // Under G41/G42 with CFC the compensation stage scales each block's feed by its own tool-centre
  // to contour length ratio, which differs by a few per mille from chord to chord: the run holds
  // as long as the contour feed and the centre feed stay within MD20172 (the profile's 1 mm/s
  // here allows far more than these 0.4 % of 50 mm/s).
  const auto m = compressed_ten_blocks([](PathElement& c, int k) {
    c.feed_scale = 1.04 + 0.001 * (k % 4);
    c.feed_mm_s *= c.feed_scale;
  });
  ASSERT_EQ(m.size(), 2u);  // the G0, then one span of all ten blocks
  EXPECT_EQ(m[1].compressed_blocks, 10u);
}

TEST(BlockCompressor, FurtherAxesOfTheBlocksMoveWithTheirSpan) {
  // Ten compressible 1 mm blocks, each turning C by 0.5 deg: one span turns C from where the
  // first block found it (30) by 10 x 0.5 = 5 deg.
  const auto m = compressed_ten_blocks([](PathElement& c, int k) {
    c.extra_axes.push_back({5, "C", 30.0 + 0.5 * k, 0.5, false});
  });
  ASSERT_EQ(m.size(), 2u);
  ASSERT_EQ(m[1].compressed_blocks, 10u);
  ASSERT_EQ(m[1].extra_axes.size(), 1u);
  EXPECT_EQ(m[1].extra_axes[0].name, "C");
  EXPECT_DOUBLE_EQ(m[1].extra_axes[0].start, 30.0);
  EXPECT_DOUBLE_EQ(m[1].extra_axes[0].travel, 5.0);
}

TEST(BlockCompressor, AFurtherAxisChangingItsRateCutsTheRunWhereItChanges) {
  // C turns 0.5 deg/mm throughout; A stands for blocks 1..4 and turns 1 deg/mm from block 5 on.
  // A span moves its axes linearly along its path: one span over all ten blocks would turn A at
  // 0.6 deg/mm from X0, 2.4 deg away from the programmed A0 at X4, far beyond MD33100 (0.1 deg,
  // the default). The line from X0 through block 5's end (A1 at X5, 0.2 deg/mm) misses A0 at X4
  // by 0.8 deg, so the run is cut after block 4: span X0..X4 turns C 2 deg from 30 (A stands),
  // span X4..X10 turns C 3 deg from 32 and A 6 deg from 0, each at its programmed rate.
  const auto m = compressed_ten_blocks([](PathElement& c, int k) {
    c.extra_axes.push_back({5, "C", 30.0 + 0.5 * k, 0.5, false});
    if (k >= 4) c.extra_axes.push_back({3, "A", 1.0 * (k - 4), 1.0, false});
  });
  ASSERT_EQ(m.size(), 3u);
  EXPECT_EQ(m[1].compressed_blocks, 4u);
  ASSERT_EQ(m[1].extra_axes.size(), 1u);
  EXPECT_DOUBLE_EQ(m[1].extra_axes[0].start, 30.0);
  EXPECT_DOUBLE_EQ(m[1].extra_axes[0].travel, 2.0);
  EXPECT_EQ(m[2].compressed_blocks, 6u);
  ASSERT_EQ(m[2].extra_axes.size(), 2u);
  EXPECT_EQ(m[2].extra_axes[0].name, "C");
  EXPECT_DOUBLE_EQ(m[2].extra_axes[0].start, 32.0);
  EXPECT_DOUBLE_EQ(m[2].extra_axes[0].travel, 3.0);
  EXPECT_EQ(m[2].extra_axes[1].name, "A");
  EXPECT_DOUBLE_EQ(m[2].extra_axes[1].start, 0.0);
  EXPECT_DOUBLE_EQ(m[2].extra_axes[1].travel, 6.0);
  // The XY path goes on tangent-continuous across the cut.
  EXPECT_LT((m[1].curve->at(m[1].curve->length()).tangent - m[2].curve->at(0).tangent).norm(), 1e-9);
}

TEST(BlockCompressor, ASuddenRotaryTurnInsideARunKeepsItsOwnRate) {
  // C turns 0.2 deg/mm, except in block 6 (8 deg/mm): its own span, so the planner sees 8 deg/mm
  // there and not the average of a span (before 2026-11-28: one span at (9 x 0.2 + 8)/10 =
  // 0.98 deg/mm). Each cut is where the line from the stretch's start misses a programmed point by
  // more than MD33100 (0.1 deg): the line from X0 through block 6's end (C 9 at X6, 1.5 deg/mm)
  // passes 6.5 deg from C 1 at X5; the line from X5 through block 7's end (C 8.2 at X7) passes
  // 3.9 deg from C 8 at X6. Block 6 alone is no run: it stays the G1 block it is.
  const auto m = compressed_ten_blocks([](PathElement& c, int k) {
    const double turn = k == 5 ? 8.0 : 0.2;
    c.extra_axes.push_back({5, "C", 0.0, turn, false});
  });
  ASSERT_EQ(m.size(), 4u);
  EXPECT_EQ(m[1].compressed_blocks, 5u);
  EXPECT_EQ(m[2].kind, ElementKind::Line);
  EXPECT_DOUBLE_EQ(m[2].extra_axes[0].travel, 8.0);
  EXPECT_NEAR(m[2].curve->length(), 1.0, 1e-9);
  EXPECT_EQ(m[3].compressed_blocks, 4u);
}

TEST(BlockCompressor, ARotaryRateChangingWithinItsToleranceStaysOneSpan) {
  // C(x) = 0.001 x^3 over ten 1 mm blocks: the straight line from (0, 0) to (10, 1) misses the
  // cubic by at most 0.385 deg (at x = 5.77); with MD33100 = 0.5 deg the run stays whole, with
  // 0.1 deg it is cut.
  auto cubic = [](PathElement& c, int k) {
    const auto at = [](int x) { return 0.001 * x * x * x; };
    c.extra_axes.push_back({0, "C", at(k), at(k + 1) - at(k), false});
  };
  auto profile = testing::test_profile();
  machine::AxisData c_axis;
  c_axis.name = "C";
  profile.extra_axes = {c_axis};
  profile.extra_axes[0].compress_pos_tol_mm = 0.5;
  EXPECT_EQ(compressed_ten_blocks(cubic, profile).size(), 2u);  // the G0, then one span
  profile.extra_axes[0].compress_pos_tol_mm = 0.1;
  EXPECT_GT(compressed_ten_blocks(cubic, profile).size(), 2u);
}

TEST(BlockCompressor, ALongRunIsFlushedInWindowsAndStaysTangentContinuous) {
  auto p = testing::test_profile();
  p.compressor.flush_points = 100;
  std::string text = "G0 X0 Y0 Z0\nG64 COMPCAD F3000\n";
  for (int i = 1; i <= 450; ++i) text += "G1 X" + std::to_string(0.1 * i) + " Y" + std::to_string(std::sin(0.01 * i)) + "\n";
  const auto m = compressed(text + "M30\n", p);
  uint32_t blocks = 0;
  for (size_t i = 1; i < m.size(); ++i) {
    blocks += m[i].compressed_blocks > 0 ? m[i].compressed_blocks : 1;
    const auto a = m[i - 1].curve->at(m[i - 1].curve->length()).tangent, b = m[i].curve->at(0).tangent;
    if (i > 1) {
      EXPECT_LT((a - b).norm(), 1e-6) << "junction " << i;
    }
  }
  EXPECT_EQ(blocks, 450u);
  EXPECT_GE(m.size(), 1u + 5u);  // at least one span per window of 100 points
}

// 200 short G1 blocks along a wave, and the largest deviation of the compressed spans.
std::string wave_blocks() {
  std::string wave;
  for (int i = 1; i <= 200; ++i)
    wave += "G1 X" + std::to_string(0.5 * i) + " Y" + std::to_string(0.3 * std::sin(0.7 * i)) + "\n";
  return wave;
}

double largest(const std::vector<PathElement>& m) {
  double d = 0;
  for (const auto& e : m) d = std::max(d, e.compressed_blocks > 0 ? e.compress_deviation_mm : 0.0);
  return d;
}

TEST(BlockCompressor, CtolReplacesTheContourToleranceOfTheRuns) {
  // MD20482 units digit 1: the contour tolerance SD42475 (0.05 mm), or CTOL= in the program.
  auto p = testing::test_profile();
  p.compressor.mode = 1;
  p.compressor.contur_tol_mm = 0.05;
  const std::string wave = wave_blocks();
  const auto data = compressed("G0 X0 Y0 Z0\nG64 COMPCAD F3000\n" + wave + "M30\n", p);
  const auto ctol = compressed("G0 X0 Y0 Z0\nG64 COMPCAD F3000\nCTOL=0.002\n" + wave + "M30\n", p);
  const auto reset = compressed("G0 X0 Y0 Z0\nG64 COMPCAD F3000\nCTOL=0.002\nCTOL=-1\n" + wave + "M30\n", p);
  EXPECT_GT(largest(data), 0.002);  // the data's 0.05 mm is used
  EXPECT_LE(largest(ctol), 0.002 + 1e-12);
  EXPECT_GT(ctol.size(), data.size());
  EXPECT_DOUBLE_EQ(largest(reset), largest(data));
}

TEST(BlockCompressor, CtolHoldsUnderTheAxisToleranceMode) {
  // MD20482 units digit 0: the axis tolerances MD33100 (0.1 mm here) apply to the runs; a
  // programmed CTOL holds anyway, before ATOL (Job Planning, "CTOL, OTOL, ATOL").
  auto p = testing::test_profile();
  p.compressor.mode = 0;
  for (auto& axis : p.axes) axis.compress_pos_tol_mm = 0.1;
  const std::string wave = wave_blocks();
  const auto data = compressed("G0 X0 Y0 Z0\nG64 COMPCAD F3000\n" + wave + "M30\n", p);
  const auto ctol = compressed("G0 X0 Y0 Z0\nG64 COMPCAD F3000\nCTOL=0.002 ATOL[X]=0.05 ATOL[Y]=0.05\n" + wave + "M30\n", p);
  EXPECT_GT(largest(data), 0.002);
  EXPECT_LE(largest(ctol), 0.002 + 1e-12);
}


TEST(BlockCompressor, FlatOutsideCornersUnderG42StayInTheRun) {
  // A circle R = 20 in 360 chords of 1 deg, CCW, tool radius 2 on the right (G42: outside). Each
  // joint turns 1 deg, flatter than MD20230 (10 deg): the offsets meet at their intersection, on
  // the control the blocks lengthened. Until 2026-11-29 the two pieces to and from it were
  // inserted elements that ended every run, so nothing was compressed. Now the runs hold: the
  // spans carry (nearly) all 360 blocks and stay within the axis tolerance (0.1 mm) of the
  // offset polygon, whose edges lie R cos(0.5 deg) + 2 from the centre and whose vertices
  // (R cos(0.5 deg) + 2) / cos(0.5 deg) from it.
  const auto profile = testing::test_profile();
  constexpr double kR = 20.0, kRadius = 2.0, kTol = 0.1;
  std::string text = "T1 D1 M6\nG0 X30 Y0 Z0\nG64 COMPCAD F3000\nG42 G1 X20 Y0\n";
  char buf[64];
  for (int k = 1; k <= 360; ++k) {
    const double a = k * std::numbers::pi / 180.0;
    std::snprintf(buf, sizeof buf, "X%.6f Y%.6f\n", kR * std::cos(a), kR * std::sin(a));
    text += buf;
  }
  text += "G40 G1 X30 Y0\nM30\n";
  auto run = testing::run_program(text, profile);
  ASSERT_FALSE(run->alarm) << run->alarm->format();
  CollectingSink out;
  BlockCompressor compressor(out, profile);
  Diagnostics diagnostics;
  CutterCompensation compensation(compressor, profile, diagnostics);
  for (auto& e : run->sink.elements) compensation.consume(PathElement(e));
  compensation.finish();
  uint32_t blocks = 0;
  const double half = 0.5 * std::numbers::pi / 180.0;
  const double edge = kR * std::cos(half) + kRadius, vertex = edge / std::cos(half);
  for (const PathElement& e : out.motions()) {
    if (e.kind != ElementKind::SplineSpan) continue;
    blocks += e.compressed_blocks;
    for (int i = 0; i <= 20; ++i) {
      const Eigen::Vector3d p = e.curve->at(e.curve->length() * i / 20.0).position;
      const double rho = std::hypot(p.x(), p.y());
      EXPECT_GE(rho, edge - kTol - 1e-9);
      EXPECT_LE(rho, vertex + kTol + 1e-9);
    }
  }
  EXPECT_GE(blocks, 355u);
  EXPECT_LE(blocks, 360u);
}

}  // namespace
}  // namespace drycut::interp
