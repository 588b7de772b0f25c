// Properties of the compressor fit (compressor_fit.hpp), checked by an independent distance
// computation: dense samples of every span against the programmed polyline (point-to-segment
// distance), every programmed point against the dense samples, continuity at span junctions,
// corners passed exactly, at most 10 blocks per COMPON/COMPCURV span.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "interp/geometry/compressor_fit.hpp"

namespace drycut::geometry {
namespace {

double point_segment_distance(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double len2 = ab.squaredNorm();
  const double f = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (p - (a + f * ab)).norm();
}

double distance_to_polyline(const Vec3& p, const std::vector<Vec3>& pts, size_t first, size_t last) {
  double best = 1e300;
  for (size_t i = first; i < last; ++i) best = std::min(best, point_segment_distance(p, pts[i], pts[i + 1]));
  return best;
}

// Dense samples of one fitted span (a straight span as its programmed segment).
std::vector<Vec3> span_samples(const FittedSpan& s, const std::vector<Vec3>& pts) {
  constexpr int kSamples = 400;
  std::vector<Vec3> out;
  for (int k = 0; k <= kSamples; ++k) {
    const double f = static_cast<double>(k) / kSamples;
    out.push_back(s.curve ? s.curve->at(f * s.curve->length()).position : Vec3(pts[s.first] + f * (pts[s.last] - pts[s.first])));
  }
  return out;
}

struct BandResult {
  double path_to_polyline = 0;  // largest distance of the fitted path from the programmed polyline
  double point_to_path = 0;     // largest distance of a programmed point from the fitted path
};

// A programmed point's distance is measured to the spans that replace the blocks ending or
// starting there only: an upper bound of its distance to the whole path, so the check is no
// weaker, and linear in the run's length (the sanitized suite runs this at -O0).
BandResult measure_band(const std::vector<FittedSpan>& spans, const std::vector<Vec3>& pts) {
  BandResult r;
  std::vector<double> point_distance(pts.size(), 1e300);
  for (const auto& s : spans) {
    const std::vector<Vec3> samples = span_samples(s, pts);
    // Each span stays near the programmed polyline it replaces (a window of it is enough).
    for (const Vec3& p : samples) r.path_to_polyline = std::max(r.path_to_polyline, distance_to_polyline(p, pts, s.first, s.last));
    for (size_t j = s.first; j <= s.last; ++j) {
      for (size_t i = 0; i + 1 < samples.size(); ++i)
        point_distance[j] = std::min(point_distance[j], point_segment_distance(pts[j], samples[i], samples[i + 1]));
    }
  }
  for (double d : point_distance) r.point_to_path = std::max(r.point_to_path, d);
  return r;
}

void expect_covering(const std::vector<FittedSpan>& spans, size_t n) {
  ASSERT_FALSE(spans.empty());
  EXPECT_EQ(spans.front().first, 0u);
  EXPECT_EQ(spans.back().last, n);
  for (size_t j = 1; j < spans.size(); ++j) EXPECT_EQ(spans[j].first, spans[j - 1].last);
}

Vec3 start_tangent(const FittedSpan& s, const std::vector<Vec3>& pts) {
  return s.curve ? s.curve->at(0).tangent : Vec3((pts[s.last] - pts[s.first]).normalized());
}
Vec3 end_tangent(const FittedSpan& s, const std::vector<Vec3>& pts) {
  return s.curve ? s.curve->at(s.curve->length()).tangent : Vec3((pts[s.last] - pts[s.first]).normalized());
}

std::vector<Vec3> circle_points(double radius, double chord) {
  const int n = static_cast<int>(std::ceil(2 * std::numbers::pi * radius / chord));
  std::vector<Vec3> pts;
  for (int i = 0; i <= n; ++i) {
    const double a = 2 * std::numbers::pi * i / n;
    pts.emplace_back(radius * std::cos(a), radius * std::sin(a), 0);
  }
  return pts;
}

// A wavy free-form line in space: a sine in Y with a slow drift in Z.
std::vector<Vec3> wavy_points(int n, double step) {
  std::vector<Vec3> pts;
  for (int i = 0; i <= n; ++i) {
    const double x = i * step;
    pts.emplace_back(x, 3.0 * std::sin(x / 4.0) + 0.5 * std::sin(x / 1.3), 0.2 * std::cos(x / 7.0));
  }
  return pts;
}

CompressorFitOptions options_for(FitContinuity c, size_t max_segments, bool contour, double tol) {
  CompressorFitOptions o;
  o.continuity = c;
  o.max_segments_per_span = max_segments;
  o.contour_tolerance = contour;
  o.contour_tol_mm = tol;
  o.axis_tol_mm = Vec3::Constant(tol);
  o.corner_angle_deg = max_segments == 0 ? 36.0 : 180.0;
  return o;
}

struct Mode {
  const char* name;
  FitContinuity continuity;
  size_t max_segments;
};
constexpr Mode kModes[] = {{"COMPON", FitContinuity::C1, 10}, {"COMPCURV", FitContinuity::C2, 10},
                           {"COMPCAD", FitContinuity::C2, 0}};

TEST(CompressorFit, CollinearPointsBecomeOneStraightSpan) {
  std::vector<Vec3> pts;
  for (int i = 0; i <= 10; ++i) pts.emplace_back(0.3 * i, 0.1 * i, 0);
  const auto spans = fit_compressed_run(pts, options_for(FitContinuity::C2, 0, true, 0.01));
  ASSERT_EQ(spans.size(), 1u);
  ASSERT_TRUE(spans[0].curve);
  EXPECT_NEAR(spans[0].curve->length(), (pts.back() - pts.front()).norm(), 1e-9);
  EXPECT_LT(spans[0].curve->max_curvature(), 1e-9);
  EXPECT_LT(spans[0].deviation_mm, 1e-12);
}

TEST(CompressorFit, EveryModeStaysInTheToleranceBandOnACircleAndAWavyLine) {
  for (const Mode& mode : kModes) {
    for (bool contour : {true, false}) {
      for (const auto& pts : {circle_points(20.0, 0.5), wavy_points(300, 0.2)}) {
        const double tol = 0.01;
        const auto spans = fit_compressed_run(pts, options_for(mode.continuity, mode.max_segments, contour, tol));
        expect_covering(spans, pts.size() - 1);
        const BandResult band = measure_band(spans, pts);
        // Per-axis tolerance bounds each axis: the distance is at most sqrt(3) of it.
        const double allowed = contour ? tol : tol * std::sqrt(3.0);
        EXPECT_LE(band.path_to_polyline, allowed) << mode.name << " contour=" << contour;
        EXPECT_LE(band.point_to_path, allowed) << mode.name << " contour=" << contour;
        EXPECT_LT(spans.size(), pts.size() / 2) << mode.name << ": the smooth run is compressed";
      }
    }
  }
}

TEST(CompressorFit, NoisyZigzagStaysInTheBandThroughStraightFallbacks) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> noise(-0.2, 0.2);
  std::vector<Vec3> pts;
  for (int i = 0; i <= 200; ++i) pts.emplace_back(0.1 * i, noise(rng), 0.5 * noise(rng));
  for (const Mode& mode : kModes) {
    const auto spans = fit_compressed_run(pts, options_for(mode.continuity, mode.max_segments, true, 0.02));
    expect_covering(spans, pts.size() - 1);
    const BandResult band = measure_band(spans, pts);
    EXPECT_LE(band.path_to_polyline, 0.02) << mode.name;
    EXPECT_LE(band.point_to_path, 0.02) << mode.name;
  }
}

TEST(CompressorFit, ComponAndCompcurvJoinAtMostTenBlocksPerSpan) {
  const auto pts = wavy_points(200, 0.05);
  for (const Mode& mode : kModes) {
    if (mode.max_segments == 0) continue;
    const auto spans = fit_compressed_run(pts, options_for(mode.continuity, mode.max_segments, true, 0.05));
    for (const auto& s : spans) EXPECT_LE(s.last - s.first, 10u) << mode.name;
  }
  // COMPCAD is not bounded: a straight run of 100 blocks is one span.
  std::vector<Vec3> line;
  for (int i = 0; i <= 100; ++i) line.emplace_back(0.1 * i, 0, 0);
  EXPECT_EQ(fit_compressed_run(line, options_for(FitContinuity::C2, 0, true, 0.01)).size(), 1u);
}

TEST(CompressorFit, TangentContinuousInsideARunAndCurvatureContinuousForC2) {
  for (const Mode& mode : kModes) {
    const auto pts = wavy_points(300, 0.2);
    const auto spans = fit_compressed_run(pts, options_for(mode.continuity, mode.max_segments, true, 0.01));
    int curved_junctions = 0;
    for (size_t j = 1; j < spans.size(); ++j) {
      const FittedSpan &a = spans[j - 1], &b = spans[j];
      if (!a.curve || !b.curve) continue;  // a straight fallback segment meets its neighbours at a corner
      ++curved_junctions;
      EXPECT_LT((end_tangent(a, pts) - start_tangent(b, pts)).norm(), 1e-7) << mode.name << " junction " << j;
      if (mode.continuity == FitContinuity::C2) {
        const Vec3 ka = a.curve->at(a.curve->length()).curvature_vector, kb = b.curve->at(0).curvature_vector;
        EXPECT_LT((ka - kb).norm(), 1e-6 * (1.0 + ka.norm())) << mode.name << " junction " << j;
      }
    }
    EXPECT_GT(curved_junctions, 3) << mode.name;
  }
}

TEST(CompressorFit, CompcadPassesADetectedCornerExactlyAndTurnsThere) {
  // Two straight runs of 0.5 mm blocks meeting at 90 degrees at (5, 0).
  std::vector<Vec3> pts;
  for (int i = 0; i <= 10; ++i) pts.emplace_back(0.5 * i, 0, 0);
  for (int i = 1; i <= 10; ++i) pts.emplace_back(5, 0.5 * i, 0);
  const auto spans = fit_compressed_run(pts, options_for(FitContinuity::C2, 0, true, 0.05));
  ASSERT_EQ(spans.size(), 2u);
  EXPECT_EQ(spans[0].last, 10u);
  EXPECT_LT((spans[0].curve->end() - pts[10]).norm(), 1e-12);
  EXPECT_LT((spans[1].curve->start() - pts[10]).norm(), 1e-12);
  EXPECT_NEAR(end_tangent(spans[0], pts).dot(start_tangent(spans[1], pts)), 0.0, 1e-9);
  // 30 degrees is below the 36 degree corner angle: smoothed, not a corner; 40 degrees is one.
  for (double angle : {30.0, 40.0}) {
    std::vector<Vec3> bent;
    for (int i = 0; i <= 10; ++i) bent.emplace_back(0.5 * i, 0, 0);
    const double a = angle * std::numbers::pi / 180.0;
    for (int i = 1; i <= 10; ++i) bent.emplace_back(5 + 0.5 * i * std::cos(a), 0.5 * i * std::sin(a), 0);
    const auto s = fit_compressed_run(bent, options_for(FitContinuity::C2, 0, true, 0.05));
    bool corner_at_10 = false;
    for (size_t j = 1; j < s.size(); ++j)
      if (s[j].first == 10 && (end_tangent(s[j - 1], bent) - start_tangent(s[j], bent)).norm() > 1e-3) corner_at_10 = true;
    EXPECT_EQ(corner_at_10, angle > 36.0) << angle;
    const BandResult band = measure_band(s, bent);
    EXPECT_LE(band.path_to_polyline, 0.05) << angle;
  }
}

TEST(CompressorFit, AGivenStartTangentIsKept) {
  const auto pts = circle_points(20.0, 0.5);
  const Vec3 tangent(0, 1, 0);  // the circle's own tangent at (20, 0)
  const auto spans = fit_compressed_run(pts, options_for(FitContinuity::C2, 0, true, 0.01), tangent);
  ASSERT_TRUE(spans.front().curve);
  EXPECT_LT((spans.front().curve->at(0).tangent - tangent).norm(), 1e-9);
}

}  // namespace
}  // namespace drycut::geometry
