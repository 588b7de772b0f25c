// Tool radius compensation on sloped blocks (issue 16): the compensation works in the plane, the
// normal axis follows the programmed blocks, and where blocks are shortened, cut or joined the
// motion along the normal is spread so that no element moves Z alone. Checked against
// independent computations: the in-plane distance of every tool-centre sample to the programmed
// polygon, Z monotone along a monotone program, Z at the points where the tool centre is in step
// with the program, the pitch of a helix (from the sampled angle about its axis), and the
// spreading rule of cutter_compensation_normal_axis by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <vector>

#include "compensation_test_curves.hpp"
#include "cutter_compensation_test_support.hpp"
#include "interp/cutter_compensation.hpp"
#include "interp/cutter_compensation_normal_axis.hpp"
#include "interp/geometry/arc_curve.hpp"

namespace drycut::interp {
namespace {

using geometry::Vec3;
using test::Comp;
using test::line;
using Point2 = Eigen::Vector2d;
constexpr double kPi = std::numbers::pi;

using test::StageRun;

Point2 xy(const Vec3& p) { return {p.x(), p.y()}; }

// ---------------------------------------------------------------- the spreading rule by hand

TEST(NormalAxisSpread, UntouchedSpanKeepsItsOwnMotion) {
  EXPECT_DOUBLE_EQ(normal_value_at_end(0.0, {{5.0, 0.0, 1.0, false, true, 1}}), 1.0);
}

TEST(NormalAxisSpread, BothPiecesOfAnInsideCornerMeetAtOneValueWithOneSlope) {
  // A' 3 mm in the plane, natural 0 -> 0.3, shortened at its end; B' 2 mm, natural 0.5 -> 0.7,
  // shortened at its start and in step at its end. Natural rises 0.3 + 0.2, needed 0.7: the
  // skipped 0.2 is shared 3 : 2, so A' ends at 0.3 + 0.12 = 0.42 and both climb 0.14 per mm.
  const NormalAxisSpan a{3.0, 0.0, 0.3, false, false, 1}, b{2.0, 0.5, 0.7, false, true, 2};
  const double a_end = normal_value_at_end(0.0, {a, b});
  EXPECT_NEAR(a_end, 0.42, 1e-12);
  const double b_end = normal_value_at_end(a_end, {b});
  EXPECT_NEAR(b_end, 0.7, 1e-12);
  EXPECT_NEAR(a_end / 3.0, (b_end - a_end) / 2.0, 1e-12);
}

TEST(NormalAxisSpread, InsertedCircleSharesTheSlopeOfItsBlock) {
  // A transition circle of 1 mm (flat at the corner, inserted, block 2) before its block's
  // piece, 4 mm from 0 down to -0.4 and in step at its end. Borrowed rise -0.1, natural sum -0.5,
  // needed -0.4: +0.1 shared 1 : 4, so the circle ends at -0.08 and the piece falls 0.32 over
  // 4 mm: both -0.08 per mm.
  const NormalAxisSpan circle{1.0, 0.0, 0.0, true, true, 2}, piece{4.0, 0.0, -0.4, false, true, 2};
  const double circle_end = normal_value_at_end(0.0, {circle, piece});
  EXPECT_NEAR(circle_end, -0.08, 1e-12);
  EXPECT_NEAR(normal_value_at_end(circle_end, {piece}), -0.4, 1e-12);
}

TEST(NormalAxisSpread, FlatSpanStaysFlat) {
  // An approach at Z10 (30 mm, shortened at its end) before a ramp (10 mm, natural 5 -> 0.5,
  // shortened at its start): the approach stays at 10, the ramp takes all of 10 -> 0.5.
  const NormalAxisSpan approach{30.0, 10.0, 10.0, false, false, 1}, ramp{10.0, 5.0, 0.5, false, true, 2};
  EXPECT_DOUBLE_EQ(normal_value_at_end(10.0, {approach, ramp}), 10.0);
  EXPECT_DOUBLE_EQ(normal_value_at_end(10.0, {ramp}), 0.5);
}

TEST(NormalAxisSpread, FlatStretchSpreadsOverItsInPlaneLength) {
  // Nothing moves by itself but 0.6 mm are left over from before (tool at 0, anchor at 0.6):
  // shared by in-plane length 1 : 2.
  const NormalAxisSpan a{1.0, 0.6, 0.6, false, false, 1}, b{2.0, 0.6, 0.6, false, true, 2};
  EXPECT_NEAR(normal_value_at_end(0.0, {a, b}), 0.2, 1e-12);
}

TEST(NormalAxisSpread, SpanWithoutInPlaneLengthDoesNotMove) {
  EXPECT_DOUBLE_EQ(normal_value_at_end(3.0, {{0.0, 3.0, 4.0, false, true, 1}}), 3.0);
}

TEST(NormalAxisSpread, PassengerTravelIsNotCountedTwice) {
  // A piece 0 -> 0.2, a Z infeed of +1 (no in-plane length), a piece 1.2 -> 1.4 in step: nothing
  // is skipped, so the first piece keeps its own 0.2.
  const NormalAxisSpan a{2.0, 0.0, 0.2, false, false, 1}, infeed{0.0, 0.0, 1.0, false, false, 1},
      b{2.0, 1.2, 1.4, false, true, 2};
  EXPECT_NEAR(normal_value_at_end(0.0, {a, infeed, b}), 0.2, 1e-12);
}

// ---------------------------------------------------------------- a sloped polygon

// An open chevron, counter-clockwise: two convex corners, (30, 0) and (30, 20), and a reflex
// corner at (15, 8). Milled descending at a grade of 0.05 (Z = -0.05 * programmed in-plane length
// so far).
const std::vector<Point2> kChevron = {{0, 0}, {30, 0}, {30, 20}, {15, 8}, {0, 20}};
constexpr double kGrade = 0.05;
constexpr double kRadius = 2.0;

std::vector<double> chevron_z() {
  std::vector<double> z{0.0};
  for (size_t i = 1; i < kChevron.size(); ++i) z.push_back(z.back() - kGrade * (kChevron[i] - kChevron[i - 1]).norm());
  return z;
}

Vec3 at3(size_t i) { return {kChevron[i].x(), kChevron[i].y(), chevron_z()[i]}; }

// Approach (line 1, flat at Z0), the four edges (lines 2..5), G40 retract (line 6, flat).
std::vector<PathElement> sloped_chevron(const Comp& comp) {
  std::vector<PathElement> out{line({-10, -10, 0}, at3(0), comp, 1)};
  for (size_t i = 0; i + 1 < kChevron.size(); ++i)
    out.push_back(line(at3(i), at3(i + 1), comp, static_cast<uint32_t>(i + 2)));
  const double z_end = chevron_z().back();
  out.push_back(line(at3(kChevron.size() - 1), {-10, 30, z_end}, comp.off(), 6));
  return out;
}

double distance_to_chevron(const Point2& p) {
  double best = std::numeric_limits<double>::infinity();
  for (size_t i = 1; i < kChevron.size(); ++i) {
    const Point2 a = kChevron[i - 1], ab = kChevron[i] - a;
    const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    best = std::min(best, (a + t * ab - p).norm());
  }
  return best;
}

// Unit direction of travel in the plane and in space at arc length s (by a chord: independent of
// the curve's own tangent).
Vec3 chord_direction(const geometry::Curve& c, double s0, double s1) { return (c.at(s1).position - c.at(s0).position).normalized(); }

struct ChevronResult {
  int arcs = 0;
  double largest_tangential_kink = 0.0;  // rad, 3-D direction change where the plane has none
};

ChevronResult check_sloped_chevron(const std::vector<PathElement>& out, bool g451) {
  ChevronResult result;

  const std::vector<double> z = chevron_z();
  test::expect_continuous(out, 1e-9);
  double previous_z = 0.0;
  for (size_t k = 0; k < out.size(); ++k) {
    const PathElement& e = out[k];
    const geometry::Curve& c = *e.curve;
    if (e.kind == ElementKind::Arc) ++result.arcs;
    // Every element moves in the plane (the program has no Z-only block).
    double in_plane = 0.0;
    for (int i = 1; i <= 16; ++i) in_plane = std::max(in_plane, (xy(c.at(c.length() * i / 16).position) - xy(c.start())).norm());
    EXPECT_GT(in_plane, 1e-3) << "element " << k << " (line " << e.source.line << ") moves Z alone";
    for (int i = 0; i <= 16; ++i) {
      const Vec3 p = c.at(c.length() * i / 16).position;
      // Z never rises along the descending program.
      EXPECT_LE(p.z(), previous_z + 1e-9) << "element " << k << " sample " << i;
      previous_z = p.z();
      if (e.source.line < 2 || e.source.line > 5) continue;
      const double d = distance_to_chevron(xy(p));
      if (g451 && e.inserted)
        EXPECT_GE(d, kRadius - 1e-9) << "element " << k;  // the intersection lines stand off the corner
      else
        EXPECT_NEAR(d, kRadius, 1e-9) << "element " << k << " sample " << i;
    }
    // Where the tool centre is in step with a corner (r from the corner point: the end of an
    // edge's offset, the start of the element inserted there) it is at the corner's programmed Z.
    if (e.source.line >= 2 && e.source.line <= 5)
      for (size_t v = 1; v + 1 < kChevron.size(); ++v) {
        const Vec3 p = e.inserted ? c.start() : c.end();
        if (std::abs((xy(p) - kChevron[v]).norm() - kRadius) < 1e-9) {
          EXPECT_NEAR(p.z(), z[v], 1e-9) << "corner " << v;
        }
      }
    // Joints where the plane turns smoothly (transition circles): only the slope may change.
    if (k > 0) {
      const geometry::Curve& b = *out[k - 1].curve;
      const double h = 1e-4;
      const Vec3 t_in = chord_direction(b, b.length() - h, b.length()), t_out = chord_direction(c, 0.0, h);
      const Vec3 p_in(t_in.x(), t_in.y(), 0.0), p_out(t_out.x(), t_out.y(), 0.0);
      const double plane_turn = std::acos(std::clamp(p_in.normalized().dot(p_out.normalized()), -1.0, 1.0));
      if (plane_turn < 1e-3)
        result.largest_tangential_kink =
            std::max(result.largest_tangential_kink, std::acos(std::clamp(t_in.dot(t_out), -1.0, 1.0)));
    }
  }
  // The contour ends in step at the programmed end depth; the retract stays there.
  EXPECT_NEAR(out.back().curve->start().z(), z.back(), 1e-9);
  EXPECT_NEAR(out.back().curve->end().z(), z.back(), 1e-9);
  EXPECT_NEAR(out.front().curve->end().z(), 0.0, 1e-9);  // the approach ends in step at Z0
  return result;
}

// Where the plane turns smoothly only the slope may change. A flat transition circle would kink
// by atan(0.05) = 0.05 rad at both ends. The tool centre is at the programmed Z where it is in
// step with the program, so a stretch the compensation shortened (inside corners) is steeper and
// one it lengthened (circles) flatter. By hand for G41/G450: from the approach end (Z 0) to the
// circle at (15, 8) (Z -3.4605) the tool centre runs 28 + 13.839 + 15.048 = 56.887 mm in the
// plane (slope 0.0608); the circle (2 * 1.349 mm) and the last edge (19.209 mm) share that
// edge's 0.9605 mm (slope 0.0438): a kink of 0.017 rad (G451: lines of 2 * 1.599 mm, 0.018 rad).
constexpr double kKinkBound = 0.02;

TEST(CutterCompensationSloped, ChevronG41InsideCornersHaveNoVerticalStep) {
  // G41 on the counter-clockwise chevron: the tool is inside, so the two convex corners are
  // inside corners (the offsets are intersected) and the reflex corner (a 77.3 degree turn) is
  // an outside corner: a transition circle (G450) or the intersection lines (G451).
  for (bool g451 : {false, true}) {
    StageRun run;
    run.feed(sloped_chevron(Comp{.side = CompensationSide::Left, .g451 = g451}));
    ASSERT_FALSE(run.diagnostics.has_alarms());
    const ChevronResult r = check_sloped_chevron(run.sink.motions(), g451);
    EXPECT_EQ(r.arcs, g451 ? 0 : 1) << g451;
    EXPECT_LT(r.largest_tangential_kink, kKinkBound) << g451;
  }
}

TEST(CutterCompensationSloped, ChevronG42OutsideCornersAndOneInsideCorner) {
  // G42: the convex corners are outside corners (90 and 128.7 degrees: G451 keeps the circle
  // above the 100 degree corner limit), the reflex corner is an inside corner.
  for (bool g451 : {false, true}) {
    StageRun run;
    run.feed(sloped_chevron(Comp{.side = CompensationSide::Right, .g451 = g451}));
    ASSERT_FALSE(run.diagnostics.has_alarms());
    const ChevronResult r = check_sloped_chevron(run.sink.motions(), g451);
    EXPECT_EQ(r.arcs, g451 ? 1 : 2) << g451;
    EXPECT_LT(r.largest_tangential_kink, kKinkBound) << g451;
  }
}

TEST(CutterCompensationSloped, InsideCornerInTheG18PlaneMeetsAtOneValueOfY) {
  // G18: plane (Z, X), normal Y. An L in plane coordinates (0,0) -> (20,0) -> (20,20), Y falling
  // 1 mm per edge, G41 inside the left turn, r = 2: the offsets meet at plane point (18, 2), and
  // each edge skips 2 mm of its 20 (0.1 mm of Y). Both pieces are 18 mm in the plane with the
  // same slope, so the skipped 0.2 mm is shared equally: they meet at Y = -0.9 - 0.1 = -1.
  const Comp comp{.side = CompensationSide::Left, .plane_axis = 1};
  auto g18 = [](double first, double second, double normal) { return Vec3(second, normal, first); };
  StageRun run;
  run.feed({line(g18(-10, -10, 0), g18(0, 0, 0), comp, 1), line(g18(0, 0, 0), g18(20, 0, -1), comp, 2),
            line(g18(20, 0, -1), g18(20, 20, -2), comp, 3), line(g18(20, 20, -2), g18(30, 30, -2), comp.off(), 4)});
  ASSERT_FALSE(run.diagnostics.has_alarms());
  const auto out = run.sink.motions();
  ASSERT_EQ(out.size(), 4u);
  test::expect_continuous(out, 1e-9);
  EXPECT_LT((out[1].curve->end() - g18(18, 2, -1)).norm(), 1e-9) << out[1].curve->end().transpose();
  EXPECT_LT((out[2].curve->start() - g18(18, 2, -1)).norm(), 1e-9);
  EXPECT_LT((out[2].curve->end() - g18(18, 20, -2)).norm(), 1e-9);
}

// ---------------------------------------------------------------- helix and cut loops

TEST(CutterCompensationSloped, HelixKeepsItsPitch) {
  // Two counter-clockwise turns of radius 10 about (0, 0), descending 4 mm: pitch -2 mm per turn.
  // G41 puts the tool inside (radius 8), G42 outside (radius 12); either way each sample's Z is
  // -2 mm times the turns made so far (angle unwrapped from the samples themselves).
  for (auto side : {CompensationSide::Left, CompensationSide::Right}) {
    const Comp comp{.side = side};
    StageRun run;
    auto helix = std::make_shared<geometry::ArcCurve>(Vec3(0, 0, 0), 10.0, geometry::Plane::G17, 0.0, 4 * kPi, -4.0);
    run.feed({line({20, 0, 0}, {10, 0, 0}, comp, 1), test::motion(helix, ElementKind::Arc, comp, 2),
              line({10, 0, -4}, {20, 0, -4}, comp.off(), 3)});
    ASSERT_FALSE(run.diagnostics.has_alarms());
    const auto out = run.sink.motions();
    test::expect_continuous(out, 1e-9);
    const double radius = side == CompensationSide::Left ? 8.0 : 12.0;
    int samples = 0;
    double turned = 0.0, last_angle = 0.0;
    for (const auto& e : out) {
      if (e.source.line != 2) continue;
      for (int i = 0; i <= 200; ++i) {
        const Vec3 p = e.curve->at(e.curve->length() * i / 200).position;
        const double angle = std::atan2(p.y(), p.x());
        if (samples > 0) turned += std::remainder(angle - last_angle, 2 * kPi);
        last_angle = angle;
        EXPECT_NEAR(xy(p).norm(), radius, 1e-9);
        EXPECT_NEAR(p.z(), -2.0 * turned / (2 * kPi), 1e-9) << "sample " << samples;
        ++samples;
      }
    }
    EXPECT_NEAR(turned, 4 * kPi, 1e-9);
    EXPECT_GT(samples, 200);
  }
}

TEST(CutterCompensationSloped, LoopCutOnAGradedSplineLeavesNoStep) {
  // The parabola y = x^2 / 2 bends tighter than the tool on its left (radius 1 at the vertex):
  // its offset loops and is cut at (0, 2.5). Climbing at a grade of 0.1 the two sides of the cut
  // had different Z; now both reach the cut point at one Z, and Z keeps rising.
  const Comp comp{.side = CompensationSide::Left};
  auto flat = std::make_shared<test::ParabolaCurve>(0.5, -4.0, 4.0);
  auto graded = std::make_shared<test::GradedCurve>(flat, 0.1);
  const Vec3 start = graded->start(), end = graded->end();
  StageRun run;
  run.feed({line({-10, 8, start.z()}, start, comp, 1), test::motion(graded, ElementKind::SplineSpan, comp, 2),
            line(end, {10, 8, end.z()}, comp.off(), 3)});
  ASSERT_FALSE(run.diagnostics.has_alarms());
  const auto out = run.sink.motions();
  test::expect_continuous(out, 1e-9);
  double previous_z = -std::numeric_limits<double>::infinity();
  int cut_pieces = 0;
  for (const auto& e : out) {
    const Vec3 chord = e.curve->end() - e.curve->start();
    EXPECT_GT(xy(chord).norm(), 1e-3) << "line " << e.source.line << " moves Z alone";
    for (int i = 0; i <= 50; ++i) {
      const double z = e.curve->at(e.curve->length() * i / 50).position.z();
      EXPECT_GE(z, previous_z - 1e-9);
      previous_z = z;
    }
    if (e.source.line == 2) ++cut_pieces;
  }
  EXPECT_EQ(cut_pieces, 2);  // the two sides of the cut loop
  EXPECT_NEAR(out.back().curve->end().z(), end.z(), 1e-9);
}

}  // namespace
}  // namespace drycut::interp
