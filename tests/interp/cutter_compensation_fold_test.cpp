// Bottleneck detection on a fold (a bend tighter than the tool radius between tangential joints)
// against an inside corner, CDON against CDOF (docs/controller-state.md, "Bottleneck detection
// and folds").
//
// The geometry, G41 with r = 2 (tool on the left), test profile MD20240 = 3: the incoming line
// y = 0 runs to (0, 0) in +x; a wedge of phi = 30 degrees follows, i.e. the path turns left by
// 150 degrees and runs back in the direction (-cos 30, sin 30) as lines of 0.25 mm. Both offsets
// lie inside the wedge and meet on its bisector. With the virtual apex A = (a, 0) of the two
// lines (a = rho / tan(phi/2) for a fillet of radius rho, a = 0 for the sharp corner), the offset
// crossing is P = (a - r / tan(phi/2), r), and its foot on the outgoing line lies
// r / tan(phi/2) - a past the outgoing line's start. tan 15 deg = 2 - sqrt(3).
//  - Fillet rho = 0.5 (an arc of 150 deg, offset radius 0.5 - 2 < 0: a fold):
//    a = 0.5 (2 + sqrt 3) = 1.8660, P = (-1.5 (2 + sqrt 3), 2) = (-5.5981, 2), foot 5.5981 mm on,
//    in the 23rd outgoing block (5.50 .. 5.75): the arc and outgoing blocks 1..22 are cut out.
//  - Sharp corner: P = (-2 (2 + sqrt 3), 2) = (-7.4641, 2), foot 7.4641 mm on, in the 30th block.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "cutter_compensation_test_support.hpp"
#include "interp/cutter_compensation.hpp"

namespace drycut::interp {
namespace {

using geometry::Vec3;
using test::Comp;
using test::line;

constexpr double kTanHalfWedge = 2.0 - 1.7320508075688772;  // tan 15 deg
constexpr double kStep = 0.25;                               // outgoing block length
constexpr int kOutgoing = 40;

struct StageRun {
  machine::MachineProfile profile = test::test_profile();
  Diagnostics diagnostics;
  test::CollectingSink sink;
  std::optional<Alarm> alarm;
  void feed(std::vector<PathElement> elements) {
    CutterCompensation stage{sink, profile, diagnostics};
    try {
      for (auto& e : elements) stage.consume(std::move(e));
      stage.finish();
    } catch (const AlarmError& e) {
      alarm = e.alarm();
    }
  }
};

// Approach (line 1), incoming line (2), the fillet arc (3) when rho > 0, then the outgoing
// 0.25 mm lines and the G40 retract.
std::vector<PathElement> wedge(const Comp& comp, double rho) {
  const Vec3 d(-std::cos(std::numbers::pi / 6), 0.5, 0.0);
  std::vector<PathElement> out{line({-20, -5, 0}, {-20, 0, 0}, comp, 1), line({-20, 0, 0}, {0, 0, 0}, comp, 2)};
  uint32_t next = 3;
  Vec3 at(0, 0, 0);
  if (rho > 0.0) {
    const double sweep = 5.0 * std::numbers::pi / 6.0;
    auto arc = std::make_shared<geometry::ArcCurve>(Vec3(0, rho, 0), rho, geometry::Plane::G17, -std::numbers::pi / 2,
                                                    sweep, 0.0);
    at = arc->end();
    out.push_back(test::motion(arc, ElementKind::Arc, comp, next++));
  }
  for (int i = 0; i < kOutgoing; ++i, ++next) {
    out.push_back(line(at, at + kStep * d, comp, next));
    at += kStep * d;
  }
  out.push_back(line(at, at + Vec3(0, 5, 0), comp.off(), next));
  return out;
}

std::vector<uint32_t> warned_lines(const Diagnostics& diagnostics) {
  std::vector<uint32_t> lines;
  for (const Alarm& a : diagnostics.items()) {
    EXPECT_EQ(a.number, 10763) << a.format();
    lines.push_back(a.where.line);
  }
  return lines;
}

TEST(CutterCompensationFold, CdofFoldClosingBeyondMd20240IsCutWhereItCloses) {
  StageRun run;
  run.feed(wedge(Comp{.side = CompensationSide::Left, .cdon = false}, 0.5));
  ASSERT_FALSE(run.alarm) << run.alarm->format();
  const Vec3 p(-1.5 / kTanHalfWedge, 2, 0);
  const auto out = run.sink.motions();
  ASSERT_GE(out.size(), 4u);
  EXPECT_EQ(out[1].source.line, 2u);
  EXPECT_LT((out[1].curve->end() - p).norm(), 1e-6) << out[1].curve->end().transpose();
  EXPECT_EQ(out[2].source.line, 3u + 23u);  // the 23rd outgoing block, trimmed to start at P
  EXPECT_LT((out[2].curve->start() - p).norm(), 1e-6) << out[2].curve->start().transpose();
  test::expect_continuous(out);
  std::vector<uint32_t> expected;
  for (uint32_t l = 3; l <= 3 + 22; ++l) expected.push_back(l);  // the arc and outgoing blocks 1..22
  EXPECT_EQ(warned_lines(run.diagnostics), expected);
}

TEST(CutterCompensationFold, CdonFoldClosingBeyondMd20240Raises10751) {
  StageRun run;
  run.feed(wedge(Comp{.side = CompensationSide::Left, .cdon = true}, 0.5));
  ASSERT_TRUE(run.alarm);
  EXPECT_EQ(run.alarm->number, 10751);
  EXPECT_EQ(run.alarm->where.line, 3u);  // the arc whose offset runs backwards
  // With MD20240 reaching the closing block CDON cuts it exactly as CDOF does.
  StageRun wide;
  wide.profile.cutcom_maxnum_check_blocks = 24;  // from the arc (block 3) to block 26
  wide.feed(wedge(Comp{.side = CompensationSide::Left, .cdon = true}, 0.5));
  ASSERT_FALSE(wide.alarm) << wide.alarm->format();
  EXPECT_EQ(warned_lines(wide.diagnostics).size(), 23u);
}

TEST(CutterCompensationFold, CdofInsideCornerKeepsTheMd20240Reach) {
  // The sharp wedge is an inside corner between blocks: its crossing (foot 7.46 mm on, block 30
  // of the outgoing lines) lies beyond MD20240 = 3, so 10751 on the first outgoing block, whose
  // gap bridge could not be closed; with MD20240 = 30 it is cut at P.
  StageRun run;
  run.feed(wedge(Comp{.side = CompensationSide::Left, .cdon = false}, 0.0));
  ASSERT_TRUE(run.alarm);
  EXPECT_EQ(run.alarm->number, 10751);
  EXPECT_EQ(run.alarm->where.line, 3u);
  StageRun wide;
  wide.profile.cutcom_maxnum_check_blocks = 30;
  wide.feed(wedge(Comp{.side = CompensationSide::Left, .cdon = false}, 0.0));
  ASSERT_FALSE(wide.alarm) << wide.alarm->format();
  const auto out = wide.sink.motions();
  ASSERT_GE(out.size(), 3u);
  EXPECT_LT((out[1].curve->end() - Vec3(-2.0 / kTanHalfWedge, 2, 0)).norm(), 1e-6) << out[1].curve->end().transpose();
  EXPECT_EQ(out[2].source.line, 2u + 30u);
  EXPECT_EQ(warned_lines(wide.diagnostics).size(), 29u);  // outgoing blocks 1..29
}

TEST(CutterCompensationFold, CdofFoldThatNeverClosesIsABottleneck) {
  // A slot 10 mm wide ending in a semicircle of radius 5, milled inside with r = 6: the offsets
  // of the walls are the parallel lines y = 6 and y = 4 joined by a backwards semicircle of
  // radius 1, which crosses neither; the fold is still open at G40: 10751 on the arc.
  StageRun run;
  Comp comp{.side = CompensationSide::Left, .radius = 6.0, .cdon = false};
  auto arc = std::make_shared<geometry::ArcCurve>(Vec3(10, 5, 0), 5.0, geometry::Plane::G17, -std::numbers::pi / 2,
                                                  std::numbers::pi, 0.0);
  run.feed({line({-5, 0, 0}, {0, 0, 0}, comp, 1), line({0, 0, 0}, {10, 0, 0}, comp, 2),
            test::motion(arc, ElementKind::Arc, comp, 3), line({10, 10, 0}, {0, 10, 0}, comp, 4),
            line({0, 10, 0}, {-5, 10, 0}, comp.off(), 5)});
  ASSERT_TRUE(run.alarm);
  EXPECT_EQ(run.alarm->number, 10751);
  EXPECT_EQ(run.alarm->where.line, 3u);
}

TEST(CutterCompensationFold, CdofFoldOpenFor256BlocksIsACollisionWithoutWaitingForG40) {
  // A U-turn of radius 0.5 into a channel of 0.01 mm blocks that runs on beside the incoming line
  // (offsets y = 2 and y = -1, never crossing): the fold (the arc, block 3) holds the window until
  // it is 256 blocks old, so the alarm comes with the 256th channel block (serial 3 + 256), not at
  // the end of the 3000.
  machine::MachineProfile profile = test::test_profile();
  Diagnostics diagnostics;
  test::CollectingSink sink;
  CutterCompensation stage{sink, profile, diagnostics};
  Comp comp{.side = CompensationSide::Left, .cdon = false};
  std::vector<PathElement> elements{line({-20, -5, 0}, {-20, 0, 0}, comp, 1), line({-20, 0, 0}, {0, 0, 0}, comp, 2)};
  elements.push_back(test::motion(std::make_shared<geometry::ArcCurve>(Vec3(0, 0.5, 0), 0.5, geometry::Plane::G17,
                                                                       -std::numbers::pi / 2, std::numbers::pi, 0.0),
                                  ElementKind::Arc, comp, 3));
  for (int i = 0; i < 3000; ++i)
    elements.push_back(line({-0.01 * i, 1, 0}, {-0.01 * (i + 1), 1, 0}, comp, static_cast<uint32_t>(4 + i)));
  size_t consumed = 0;
  try {
    for (auto& e : elements) {
      stage.consume(std::move(e));
      ++consumed;
    }
    FAIL() << "no alarm";
  } catch (const AlarmError& e) {
    EXPECT_EQ(e.alarm().number, 10751);
    EXPECT_EQ(e.alarm().where.line, 3u);
    EXPECT_EQ(consumed, 3u + 255u);  // thrown while consuming the 256th channel block
  }
}

}  // namespace
}  // namespace drycut::interp
