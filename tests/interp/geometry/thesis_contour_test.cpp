// The reference contour of the reference experiment (programs/thesis): r = 18 + 4 cos(6 theta) cos(2 theta),
// knots every 15 deg (24) or 1 deg (360) with 3 decimals, one closed loop from (22, 0).
// Radial deviation of each spline from the true curve, sampled every 0.01 mm.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>

#include "geometry_test_support.hpp"
#include "interp/geometry/spline_builder.hpp"

namespace drycut::geometry {
namespace {

double contour_radius(double theta) { return 18 + 4 * std::cos(6 * theta) * std::cos(2 * theta); }

// Knots from `from_deg` to `to_deg` inclusive (0..360 = one closed loop from (22, 0)).
std::vector<Vec3> knots(int step_deg, int from_deg = 0, int to_deg = 360) {
  std::vector<Vec3> pts;
  for (int deg = from_deg; deg <= to_deg; deg += step_deg) {
    const double th = deg * std::numbers::pi / 180.0;
    const double r = contour_radius(th);
    auto round3 = [](double v) { return std::round(v * 1000.0) / 1000.0; };
    pts.emplace_back(round3(r * std::cos(th)), round3(r * std::sin(th)), 0.0);
  }
  return pts;
}

// Over spans [first, last) (all by default).
double max_radial_deviation(const std::vector<SplineSpan>& spans, size_t first = 0, size_t last = SIZE_MAX) {
  double worst = 0;
  for (size_t k = first; k < std::min(last, spans.size()); ++k) {
    const SplineSpan& s = spans[k];
    const double len = s.curve->length();
    for (double d = 0; d <= len; d += 0.01) {
      const Vec3 p = s.curve->at(d).position;
      worst = std::max(worst, std::abs(std::hypot(p.x(), p.y()) - contour_radius(std::atan2(p.y(), p.x()))));
    }
  }
  return worst;
}

// Shortest distance from p to the true contour (local search around p's polar angle).
double normal_distance(const Vec3& p) {
  auto dist = [&](double th) {
    const double r = contour_radius(th);
    return std::hypot(p.x() - r * std::cos(th), p.y() - r * std::sin(th));
  };
  const double th0 = std::atan2(p.y(), p.x());
  double best_th = th0, best = dist(th0);
  for (int i = -200; i <= 200; ++i) {
    const double th = th0 + i * 0.0005;
    if (dist(th) < best) { best = dist(th); best_th = th; }
  }
  double lo = best_th - 0.0005, hi = best_th + 0.0005;  // golden-section refinement
  for (int it = 0; it < 60; ++it) {
    const double a = hi - 0.618033988749895 * (hi - lo), b = lo + 0.618033988749895 * (hi - lo);
    if (dist(a) < dist(b)) hi = b; else lo = a;
  }
  return dist(0.5 * (lo + hi));
}

double max_normal_deviation(const std::vector<SplineSpan>& spans) {
  double worst = 0;
  for (const auto& s : spans)
    for (double d = 0; d <= s.curve->length(); d += 0.01) worst = std::max(worst, normal_distance(s.curve->at(d).position));
  return worst;
}

std::vector<SplineSpan> build(const std::string& method, const std::vector<Vec3>& pts, int window = 8) {
  std::unique_ptr<SplineBuilder> b;
  if (method == "A") b = make_akima_builder({});
  if (method == "B") b = make_nurbs_builder(3);
  if (method == "C") b = make_cubic_builder({}, window);
  return testing::run_spline(*b, pts, {}, std::vector<double>(pts.size(), method == "B" ? 3.0 : 1.0));
}

TEST(ThesisContour, FifteenDegreeKnots) {
  const auto pts = knots(15);
  ASSERT_EQ(pts.size(), 25u);  // 24 knots plus the start repeated to close the loop
  const auto c_window = build("C", pts, 8), c_global = build("C", pts, 0);
  const auto a = build("A", pts), b = build("B", pts);
  // The natural ends sit on the seam at (22, 0), where the contour's radius of curvature is
  // only 2.7 mm: zero curvature there is the seam defect of EXPERIMENT.md §5. Away from the
  // seam (spans 3..22) the C spline stays within 0.4 mm.
  const double cw_in = max_radial_deviation(c_window, 2, 22), cg_in = max_radial_deviation(c_global, 2, 22);
  std::cout << "15 deg knots, max radial deviation (mm), whole loop / spans 3..22:\n"
            << "  CSPLINE window 8 " << max_radial_deviation(c_window) << " / " << cw_in << "\n"
            << "  CSPLINE global   " << max_radial_deviation(c_global) << " / " << cg_in << "\n"
            << "  ASPLINE          " << max_radial_deviation(a) << " / " << max_radial_deviation(a, 2, 22) << "\n"
            << "  BSPLINE PW=3     " << max_radial_deviation(b) << " / " << max_radial_deviation(b, 2, 22) << "\n";
  EXPECT_LT(cw_in, 0.4);
  EXPECT_LT(cg_in, 0.4);
  EXPECT_GT(max_radial_deviation(c_global, 0, 1), 0.6);  // the seam defect is visible
  EXPECT_GT(max_radial_deviation(b, 2, 22), 1.0);
  EXPECT_GT(max_radial_deviation(b), 1.0);
}

TEST(ThesisContour, FifteenDegreeKnotsOverlappedAtTheSeam) {
  // EXPERIMENT.md §5: with 15 deg knots the programs overlap 2 knots before and after the seam.
  const auto pts = knots(15, -30, 390);
  ASSERT_EQ(pts.size(), 29u);
  // Spans 3..26 cover theta 0..360.
  const double c = max_radial_deviation(build("C", pts, 8), 2, 26);
  const double b = max_radial_deviation(build("B", pts), 2, 26);
  std::cout << "15 deg knots overlapped at the seam, whole loop: CSPLINE " << c << " mm, BSPLINE " << b << " mm\n";
  EXPECT_LT(c, 0.4);
  EXPECT_GT(b, 1.0);
}

TEST(ThesisContour, OneDegreeKnots) {
  const auto pts = knots(1);
  ASSERT_EQ(pts.size(), 361u);
  const auto c = build("C", pts), a = build("A", pts), b = build("B", pts);
  const double cr = max_radial_deviation(c), ar = max_radial_deviation(a), br = max_radial_deviation(b);
  const double cn = max_normal_deviation(c), an = max_normal_deviation(a), bn = max_normal_deviation(b);
  std::cout << "1 deg knots, max deviation radial / normal (mm): CSPLINE " << cr << " / " << cn << ", ASPLINE "
            << ar << " / " << an << ", BSPLINE " << br << " / " << bn << "\n";
  EXPECT_LT(cr, 0.01);
  EXPECT_LT(ar, 0.01);
  EXPECT_LT(cn, 0.01);
  EXPECT_LT(an, 0.01);
  // A cubic B spline on near-uniform knots passes P_i + (P_{i-1} - 2 P_i + P_{i+1}) / 6 + O(h^4):
  // away from the clamped ends its deviation is the largest second difference over 6, computed
  // here from the knots alone (0.0093 mm at 90 deg, where the knots are 0.385 mm apart).
  double second_difference = 0;
  for (size_t i = 1; i + 1 < pts.size(); ++i)
    second_difference = std::max(second_difference, (pts[i - 1] - 2 * pts[i] + pts[i + 1]).norm() / 6);
  const double b_interior = max_radial_deviation(b, 2, b.size() - 2);
  std::cout << "  BSPLINE away from the clamped seam " << b_interior << " (second difference / 6: "
            << second_difference << ")\n";
  EXPECT_NEAR(b_interior, second_difference, 0.05 * second_difference);
  EXPECT_LT(b_interior, 0.01);
  // The clamped ends at the seam (first and last two spans) deviate a little more.
  EXPECT_LT(bn, 0.013);
}

TEST(ThesisContour, ArcLengthOfTheOneDegreeCSplineMatchesTheContour) {
  // The thesis's contour length is 136.1895 mm; a C2 spline through 360 knots is within 0.01 %.
  double total = 0;
  for (const auto& s : build("C", knots(1))) total += s.curve->length();
  std::cout << "1 deg CSPLINE length " << total << " mm\n";
  EXPECT_NEAR(total, 136.1895, 0.014);
}

}  // namespace
}  // namespace drycut::geometry
