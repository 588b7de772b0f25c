// The corner-smoothing stage (corner_smoothing.hpp) on element streams from the real
// interpreter: the closed-form rounding of a 90-degree corner, the tolerance band checked by an
// independent distance computation, tangent continuity, G641 distances and their fall-back to G64,
// the overload-factor rule, CTOL/ATOL and the machine data.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "interp/block_compressor.hpp"
#include "interp/corner_smoothing.hpp"
#include "interp/geometry/arc_curve.hpp"
#include "interp_test_support.hpp"
#include "polyline_distance.hpp"

namespace drycut::interp {
namespace {

using geometry::Vec3;
using testing::CollectingSink;

struct Smoothed {
  std::vector<PathElement> programmed;  // the interpreter's motions
  std::vector<PathElement> out;         // after the stage
};

Smoothed smoothed(const std::string& text, const machine::MachineProfile& profile) {
  auto run = testing::run_program(text, profile);
  EXPECT_FALSE(run->alarm) << run->alarm->format();
  CollectingSink out;
  CornerSmoothing stage(out, profile);
  for (auto& e : run->sink.elements) stage.consume(PathElement(e));
  stage.finish();
  EXPECT_TRUE(out.finished);
  return {run->sink.motions(), out.motions()};
}

std::vector<std::string> labels(const std::vector<PathElement>& m) {
  std::vector<std::string> l;
  for (const auto& e : m) l.push_back(e.label);
  return l;
}

// The polyline through the programmed elements' end points (independent of the stage: plain
// point-segment distances, polyline_distance.hpp).
test::PolylineDistance programmed_polyline(const std::vector<PathElement>& programmed) {
  std::vector<Vec3> points{programmed.front().curve->start()};
  for (const auto& e : programmed) {
    EXPECT_LT((e.curve->start() - points.back()).norm(), 1e-12) << "the programmed path is connected";
    points.push_back(e.curve->end());
  }
  return test::PolylineDistance(points);
}

machine::MachineProfile contour_profile(double tol) {
  auto p = testing::test_profile();
  p.smoothing.mode = 11;  // G642 and G643: the contour tolerance SD42465
  p.smoothing.contur_tol_mm = tol;
  return p;
}

TEST(CornerSmoothing, NinetyDegreeCornerUnderG642HasTheClosedFormRounding) {
  // u1 = +X, u2 = +Y: |u2 - u1| = sqrt(2). G642 rounds with the quadratic P0, C, P3: contour
  // tolerance 0.1 mm gives the trim d = 4 * 0.1 / sqrt(2) = 0.282843 mm; the closest approach to
  // the corner is 0.1 mm, at B(1/2) = C + d/4 * (u2 - u1) = (10 - 0.070711, 0.070711).
  const auto r = smoothed("G0 X0 Y0 Z0\nG642 F3000\nG1 X10\nY10\nM30\n", contour_profile(0.1));
  ASSERT_EQ(labels(r.out), (std::vector<std::string>{"G0", "G1", "G642", "G1"}));
  const double d = 0.4 / std::sqrt(2.0);
  EXPECT_NEAR((r.out[1].curve->end() - Vec3(10 - d, 0, 0)).norm(), 0, 1e-12);
  EXPECT_NEAR((r.out[3].curve->start() - Vec3(10, d, 0)).norm(), 0, 1e-12);
  const PathElement& blend = r.out[2];
  EXPECT_TRUE(blend.inserted);
  EXPECT_EQ(blend.kind, ElementKind::SplineSpan);
  EXPECT_EQ(blend.source.line, 3u);  // the block ending at the corner
  EXPECT_NEAR(blend.smoothing_deviation_mm, 0.1, 1e-12);
  const auto& span = dynamic_cast<const geometry::PolynomialSpan&>(*blend.curve);
  const Vec3 mid = span.derivatives(0.5 * span.parameter_end()).p;
  EXPECT_NEAR((mid - Vec3(10 - 0.1 / std::sqrt(2.0), 0.1 / std::sqrt(2.0), 0)).norm(), 0, 1e-12);
  // The trimmed blocks keep their programmed length for the short-block rule.
  EXPECT_DOUBLE_EQ(r.out[1].block_length_mm, 10.0);
  EXPECT_DOUBLE_EQ(r.out[3].block_length_mm, 10.0);
  // The quadratic's second derivative is constant: 2 * (P0 - 2C + P2) = 2d * (u2 - u1).
  EXPECT_NEAR((span.derivatives(0.1).d2 - 2 * d * Vec3(-1, 1, 0)).norm(), 0, 1e-12);
  EXPECT_NEAR((span.derivatives(0.9).d2 - 2 * d * Vec3(-1, 1, 0)).norm(), 0, 1e-12);
}

TEST(CornerSmoothing, NinetyDegreeCornerUnderG645IsTheCurvatureContinuousCubic) {
  // G645: the cubic P0, C, C, P3 with d = 8 * 0.1 / sqrt(2) = 0.565685 mm; B(1/2) = C + d/8 (u2 - u1).
  const auto r = smoothed("G0 X0 Y0 Z0\nG645 F3000\nG1 X10\nY10\nM30\n", contour_profile(0.1));
  ASSERT_EQ(labels(r.out), (std::vector<std::string>{"G0", "G1", "G645", "G1"}));
  const double d = 0.8 / std::sqrt(2.0);
  EXPECT_NEAR((r.out[1].curve->end() - Vec3(10 - d, 0, 0)).norm(), 0, 1e-12);
  EXPECT_NEAR(r.out[2].smoothing_deviation_mm, 0.1, 1e-12);
  const auto& c = *r.out[2].curve;
  EXPECT_NEAR((c.at(0.5 * c.length()).position - Vec3(10 - 0.1 / std::sqrt(2.0), 0.1 / std::sqrt(2.0), 0)).norm(), 0,
              1e-9);
  EXPECT_LT(c.at(0).curvature, 1e-9);
  EXPECT_LT(c.at(c.length()).curvature, 1e-9);
}

TEST(CornerSmoothing, AxisTolerancesBoundEachAxisDeviation) {
  // MD20480 = 0 (default): MD33100 per axis. X 0.1, Y 0.02: the Y component of d/4 * (u2 - u1)
  // binds: d = 4 * 0.02 / 1 = 0.08 mm.
  auto p = testing::test_profile();
  p.axes[1].compress_pos_tol_mm = 0.02;
  const auto r = smoothed("G0 X0 Y0 Z0\nG642 F3000\nG1 X10\nY10\nM30\n", p);
  ASSERT_EQ(r.out.size(), 4u);
  EXPECT_NEAR((r.out[1].curve->end() - Vec3(9.92, 0, 0)).norm(), 0, 1e-12);
  EXPECT_NEAR(r.out[2].smoothing_deviation_mm, 0.02 * std::sqrt(2.0), 1e-12);
}

TEST(CornerSmoothing, RandomPolylinesStayInTheBandAndTangentContinuous) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> step(-5.0, 5.0), tol_pick(0.005, 0.3);
  for (int trial = 0; trial < 40; ++trial) {
    const double tol = tol_pick(rng);
    const bool contour = trial % 2 == 0;
    auto p = contour ? contour_profile(tol) : testing::test_profile();
    if (!contour)
      for (auto& a : p.axes) a.compress_pos_tol_mm = tol;
    const double band = contour ? tol : tol * std::sqrt(3.0);  // per-axis tol: at most |tol vector|
    const bool g645 = trial % 4 < 2;
    std::string text = std::string("G0 X0 Y0 Z0\n") + (g645 ? "G645" : "G643") + " BRISK F600\n";
    Vec3 at = Vec3::Zero();
    for (int i = 0; i < 30; ++i) {
      at += Vec3(step(rng), step(rng), i % 3 == 0 ? 0.3 * step(rng) : 0.0);
      char line[96];
      std::snprintf(line, sizeof line, "G1 X%.4f Y%.4f Z%.4f\n", at.x(), at.y(), at.z());
      text += line;
    }
    const auto r = smoothed(text + "M30\n", p);
    const test::PolylineDistance programmed = programmed_polyline(r.programmed);
    size_t blends = 0;
    for (size_t i = 0; i < r.out.size(); ++i) {
      const auto& c = *r.out[i].curve;
      if (r.out[i].smoothing_deviation_mm >= 0) {
        ++blends;
        EXPECT_LE(r.out[i].smoothing_deviation_mm, band + 1e-12);
      }
      for (int k = 0; k <= 200; ++k) {
        const Vec3 q = c.at(c.length() * k / 200.0).position;
        ASSERT_LE(programmed.distance(q.x(), q.y(), q.z()), band + 1e-9) << "trial " << trial << " element " << i;
      }
      if (i == 0) continue;
      const auto& prev = *r.out[i - 1].curve;
      ASSERT_LT((c.start() - prev.end()).norm(), 1e-9) << "connected at " << i;
      if (r.out[i].smoothing_deviation_mm >= 0 || r.out[i - 1].smoothing_deviation_mm >= 0) {
        EXPECT_LT((c.at(0).tangent - prev.at(prev.length()).tangent).norm(), 1e-9) << "tangent at " << i;
        // G645: curvature-continuous too, the rounding starts and ends straight.
        if (g645) {
          EXPECT_LT(c.at(0).curvature + prev.at(prev.length()).curvature, 1e-6) << "curvature at " << i;
        }
      }
    }
    // Not every corner: a rounding shorter than one IPO cycle's path (sharp turns, small
    // tolerances) is left out.
    EXPECT_GT(blends, 10u) << "most corners are rounded in trial " << trial;
  }
}

TEST(CornerSmoothing, G641RoundsAtAdisAndFallsBackToG64OnTooShortBlocks) {
  const auto p = testing::test_profile();
  // ADIS=0.5 on 10 mm blocks: the rounding starts 0.5 mm before the corner.
  auto r = smoothed("G0 X0 Y0 Z0\nG641 ADIS=0.5 F3000\nG1 X10\nY10\nM30\n", p);
  ASSERT_EQ(labels(r.out), (std::vector<std::string>{"G0", "G1", "G641", "G1"}));
  EXPECT_NEAR((r.out[1].curve->end() - Vec3(9.5, 0, 0)).norm(), 0, 1e-12);
  // ADIS=2 on a 1 mm block: half the block (0.5 mm) is 75 % short of ADIS, more than the 36 %
  // the control shortens by: the transition runs as G64 (no rounding element).
  r = smoothed("G0 X0 Y0 Z0\nG641 ADIS=2 F3000\nG1 X10\nY1\nM30\n", p);
  EXPECT_EQ(labels(r.out), (std::vector<std::string>{"G0", "G1", "G1"}));
  // ADIS=0.7 on it: 0.5 mm is 29 % short: rounded with d = 0.5.
  r = smoothed("G0 X0 Y0 Z0\nG641 ADIS=0.7 F3000\nG1 X10\nY1\nM30\n", p);
  ASSERT_EQ(labels(r.out), (std::vector<std::string>{"G0", "G1", "G641", "G1"}));
  EXPECT_NEAR((r.out[1].curve->end() - Vec3(9.5, 0, 0)).norm(), 0, 1e-12);
  // No ADIS programmed: 0, as G64.
  r = smoothed("G0 X0 Y0 Z0\nG641 F3000\nG1 X10\nY10\nM30\n", p);
  EXPECT_EQ(r.out.size(), 3u);
}

TEST(CornerSmoothing, RoundsOnlyWhereG64WouldSlowDownUnlessG643OrMd20490) {
  // A 0.06-degree bend: the overload rule lets G64 pass at F (Y velocity jump 0.001 * v allows
  // v = 5000 * 0.2 * 0.004 / 0.001 = 4000 mm/s > F), so G642 inserts nothing.
  const std::string bend = "G0 X0 Y0 Z0\nF3000\nG1 X10\nX20 Y0.01\nM30\n";
  auto p = testing::test_profile();
  EXPECT_EQ(smoothed("G642 " + bend, p).out.size(), 3u);
  EXPECT_EQ(smoothed("G643 " + bend, p).out.size(), 4u);  // G643 ignores the overload factor
  p.smoothing.ignore_ovl_factor = true;
  EXPECT_EQ(smoothed("G642 " + bend, p).out.size(), 4u);
}

TEST(CornerSmoothing, NoRoundingWhereItsCurvatureWouldBeSlowerThanTheG64Corner) {
  // ATOL 0.005 on X and Y: d = 4 * 0.005 = 0.02 mm at a 90-degree corner. G64 allows 4 mm/s
  // there. BRISK: |kappa_i| <= |u2_i - u1_i| / (2d cos²45°) = 50 /mm on the rounding, so its
  // centripetal limit is at least sqrt(0.75 * 5000 / 50) = 8.7 mm/s: rounded. SOFT (axis jerk
  // 50 m/s³, nothing else differs): its curvature jerk holds it below 4 mm/s: the rounding
  // would slow the path, the corner stays G64.
  const auto p = testing::test_profile();
  const std::string body = " F3000\nATOL[X]=0.005 ATOL[Y]=0.005\nG1 X10\nY10\nM30\n";
  EXPECT_EQ(smoothed("G0 X0 Y0 Z0\nG642 BRISK" + body, p).out.size(), 4u);
  EXPECT_EQ(smoothed("G0 X0 Y0 Z0\nG642 SOFT" + body, p).out.size(), 3u);
}

TEST(CornerSmoothing, CtolAndAtolOverrideTheDataAndNegativeRestoresThem) {
  const auto p = contour_profile(0.1);
  const std::string corner = "G1 X10\nY10\n";
  // A transition takes the settings of the block that ends there: (10, 0) and (10, 10) round
  // within CTOL = 0.02, (0, 10) after CTOL=-1 within SD42465 = 0.1 again.
  const auto r = smoothed("G0 X0 Y0 Z0\nG642 F1000\nCTOL=0.02\n" + corner + "CTOL=-1\nX0\nY0\nM30\n", p);
  ASSERT_EQ(labels(r.out), (std::vector<std::string>{"G0", "G1", "G642", "G1", "G642", "G1", "G642", "G1"}));
  EXPECT_NEAR(r.out[2].smoothing_deviation_mm, 0.02, 1e-12);
  EXPECT_NEAR(r.out[4].smoothing_deviation_mm, 0.02, 1e-12);
  EXPECT_NEAR(r.out[6].smoothing_deviation_mm, 0.1, 1e-12);
  auto axis = testing::test_profile();
  const auto a = smoothed("G0 X0 Y0 Z0\nG642 F3000\nATOL[Y]=0.01\n" + corner + "M30\n", axis);
  ASSERT_EQ(a.out.size(), 4u);
  EXPECT_NEAR(a.out[2].smoothing_deviation_mm, 0.01 * std::sqrt(2.0), 1e-12);  // d = 0.04
}

TEST(CornerSmoothing, ProgrammedCtolHoldsUnderTheAxisToleranceModeAndBeforeAtol) {
  // MD20480 = 0 (the test profile): the machine data's tolerance is MD33100 per axis (0.1 mm:
  // d = 0.1 at a right angle, deviation 0.1·√2). A programmed CTOL holds for G642 whatever
  // MD20480 selects and has priority over ATOL (Job Planning, "CTOL, OTOL, ATOL"): BRISK, so the
  // rounding's curvature does not hold it back, deviation 0.02 at both corners.
  const auto p = testing::test_profile();
  const std::string corner = "G1 X10\nY10\nX0\nM30\n";
  const auto data = smoothed("G0 X0 Y0 Z0\nG642 BRISK F1000\n" + corner, p);
  ASSERT_EQ(labels(data.out), (std::vector<std::string>{"G0", "G1", "G642", "G1", "G642", "G1"}));
  EXPECT_NEAR(data.out[2].smoothing_deviation_mm, 0.1 * std::sqrt(2.0), 1e-12);
  const auto ctol = smoothed("G0 X0 Y0 Z0\nG642 BRISK F1000\nCTOL=0.02 ATOL[X]=0.05 ATOL[Y]=0.05\n" + corner, p);
  ASSERT_EQ(labels(ctol.out), (std::vector<std::string>{"G0", "G1", "G642", "G1", "G642", "G1"}));
  EXPECT_NEAR(ctol.out[2].smoothing_deviation_mm, 0.02, 1e-12);
  EXPECT_NEAR(ctol.out[4].smoothing_deviation_mm, 0.02, 1e-12);
}

// OTOL= acts only under an orientation transformation (not modelled, warned where selected):
// accepted silently. G644 is planned as G64 and says so.
TEST(CornerSmoothing, ToleranceWordsAreModelledAndOnlyG644Warns) {
  const auto run = testing::run_program(
      "G0 X0 Y0 Z0\nCTOL=0.01 ATOL[X]=0.02 ATOL[Y]=-1 ADIS=0.5 ADISPOS=1\nOTOL=0.1\nG644 G1 X1 F1000\nM30\n");
  ASSERT_FALSE(run->alarm);
  std::vector<std::string> warned;
  for (const auto& a : run->diagnostics.items()) warned.push_back(a.text);
  ASSERT_EQ(warned.size(), 1u);
  EXPECT_NE(warned[0].find("G644"), std::string::npos) << warned[0];
  const auto motions = run->sink.motions();  // a copy: motions() returns a new vector
  ASSERT_FALSE(motions.empty());
  const auto& e = motions.back();
  EXPECT_DOUBLE_EQ(e.smoothing.ctol_mm, 0.01);
  EXPECT_DOUBLE_EQ(e.smoothing.atol_mm[0], 0.02);
  EXPECT_DOUBLE_EQ(e.smoothing.atol_mm[1], -1.0);
  EXPECT_DOUBLE_EQ(e.smoothing.adis_mm, 0.5);
  EXPECT_DOUBLE_EQ(e.smoothing.adispos_mm, 1.0);
  EXPECT_EQ(e.smoothing.code, 644);
}

TEST(CornerSmoothing, G0UsesAdisposAndTheToleranceFactor) {
  auto p = contour_profile(0.05);
  auto r = smoothed("G0 X0 Y0 Z0\nG642\nX50\nY50\nM30\n", p);
  ASSERT_EQ(r.out.size(), 4u);
  EXPECT_NEAR(r.out[2].smoothing_deviation_mm, 0.15, 1e-12);  // MD20560 = 3 x 0.05
  EXPECT_TRUE(r.out[2].rapid);
  r = smoothed("G0 X0 Y0 Z0\nG641 ADIS=0.1 ADISPOS=1\nX50\nY50\nM30\n", p);
  ASSERT_EQ(r.out.size(), 4u);
  EXPECT_NEAR((r.out[1].curve->end() - Vec3(49, 0, 0)).norm(), 0, 1e-12);
}

TEST(CornerSmoothing, G64AndShortPolyLimitPassUntouched) {
  const auto p = testing::test_profile();
  const std::string square = "G0 X0 Y0 Z0\nF3000\nG1 X10\nY10\nX0\nY0\nM30\n";
  const auto g64 = smoothed("G64 " + square, p);
  ASSERT_EQ(g64.out.size(), g64.programmed.size());
  for (size_t i = 0; i < g64.out.size(); ++i) EXPECT_EQ(g64.out[i].curve, g64.programmed[i].curve) << i;
  auto few = p;
  few.smoothing.max_axispoly_per_block = 2;  // MD28520 < 3: no G642..G645 rounding
  EXPECT_EQ(smoothed("G642 " + square, few).out.size(), 5u);
  EXPECT_EQ(smoothed("G642 " + square, p).out.size(), 8u);
  EXPECT_EQ(smoothed("G641 ADIS=1 " + square, few).out.size(), 8u);  // G641 needs no polynomials
}

}  // namespace
}  // namespace drycut::interp

namespace drycut::interp {
namespace {

using geometry::Vec3;

// A curve sampled densely (independent of the stage: a fine polyline; 5000 pieces keep the
// chord error of the r = 5 mm arc below 3e-7 mm).
test::PolylineDistance fine_polyline(const geometry::Curve& c) {
  std::vector<Vec3> points;
  for (int k = 0; k <= 5000; ++k) points.push_back(c.at(c.length() * k / 5000.0).position);
  return test::PolylineDistance(points);
}

TEST(CornerSmoothingCurves, LineIntoArcIsRoundedWithinTheContourTolerance) {
  // X0 -> X10, then G2 about (15, 0) r = 5 from (10, 0) to (20, 0): the arc starts upwards (+Y),
  // a 90-degree corner. G642 with the contour tolerance 0.05 mm.
  auto p = testing::test_profile();
  p.smoothing.mode = 10;
  p.smoothing.contur_tol_mm = 0.05;
  const auto run = testing::run_program("G0 X0 Y0 Z0\nG642 F2000\nG1 X10\nG2 X20 Y0 I5 J0\nM30\n", p);
  ASSERT_FALSE(run->alarm);
  const auto programmed = run->sink.motions();
  testing::CollectingSink out;
  CornerSmoothing stage(out, p);
  for (auto& e : run->sink.elements) stage.consume(PathElement(e));
  stage.finish();
  const auto m = out.motions();
  ASSERT_EQ(m.size(), 4u);
  EXPECT_EQ(m[2].label, "G642");
  EXPECT_LE(m[2].smoothing_deviation_mm, 0.05);
  EXPECT_GT(m[2].smoothing_deviation_mm, 0.01);  // it uses the tolerance, not a tiny share of it
  // The trimmed arc is still a circle (the planner keeps its closed form) on the programmed one.
  const auto* arc = dynamic_cast<const geometry::ArcCurve*>(m[3].curve.get());
  ASSERT_NE(arc, nullptr);
  EXPECT_NEAR((arc->at(0).position - Vec3(15, 0, 0)).norm(), 5.0, 1e-9);
  EXPECT_NEAR((m[3].curve->end() - Vec3(20, 0, 0)).norm(), 0, 1e-9);
  const test::PolylineDistance line = fine_polyline(*programmed[1].curve), circle = fine_polyline(*programmed[2].curve);
  for (size_t i = 1; i < m.size(); ++i) {
    const auto& c = *m[i].curve;
    for (int k = 0; k <= 100; ++k) {
      const Vec3 q = c.at(c.length() * k / 100.0).position;
      const double dist = std::min(line.distance(q.x(), q.y(), q.z()), circle.distance(q.x(), q.y(), q.z()));
      ASSERT_LE(dist, 0.05 + 1e-6) << "element " << i << " sample " << k;
    }
    const auto& prev = *m[i - 1].curve;
    EXPECT_LT((c.start() - prev.end()).norm(), 1e-9);
    if (i >= 2) {
      EXPECT_LT((c.at(0).tangent - prev.at(prev.length()).tangent).norm(), 1e-9) << i;
    }
  }
}

TEST(CornerSmoothingCurves, CompcadKeptCornerIsRounded) {
  // COMPCAD keeps the 90-degree corner (SD42470): two straight spans meet at (10, 0); G642 then
  // rounds it (as on the control, where CYCLE832 selects both).
  std::string text = "G0 X0 Y0 Z0\nG642 COMPCAD F3000\n";
  for (int i = 1; i <= 10; ++i) text += "G1 X" + std::to_string(i) + "\n";
  for (int i = 1; i <= 10; ++i) text += "G1 Y" + std::to_string(i) + "\n";
  auto p = testing::test_profile();
  const auto run = testing::run_program(text + "M30\n", p);
  testing::CollectingSink out;
  CornerSmoothing smoothing(out, p);
  BlockCompressor compressor(smoothing, p);
  for (auto& e : run->sink.elements) compressor.consume(PathElement(e));
  compressor.finish();
  const auto m = out.motions();
  size_t rounded = 0;
  for (size_t i = 1; i < m.size(); ++i) {
    if (m[i].label == "G642") ++rounded;
    const auto& prev = *m[i - 1].curve;
    EXPECT_LT((m[i].curve->start() - prev.end()).norm(), 1e-9) << i;
  }
  EXPECT_EQ(rounded, 1u);
}

}  // namespace
}  // namespace drycut::interp
