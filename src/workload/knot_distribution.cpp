#include "workload/knot_distribution.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <Eigen/Geometry>

namespace drycut::workload {

std::vector<Knot> parameter_step_knots(const CurveSource& curve, double step) {
  if (!(step > 0)) throw std::invalid_argument("knot step must be > 0");
  std::vector<Knot> knots;
  const double span = curve.t_end - curve.t_begin;
  const long count = std::lround(std::floor(span / step + 1e-9));
  for (long k = 0; k < count; ++k) {
    const double t = curve.t_begin + static_cast<double>(k) * step;
    if (t >= curve.t_end - 1e-12) break;
    knots.push_back({t, curve.point(t)});
  }
  return knots;
}

std::vector<Knot> equal_arc_per_quadrant_knots(const CurveSource& curve, int per_quadrant) {
  if (per_quadrant < 2) throw std::invalid_argument("at least 2 knots per quadrant");
  std::vector<Knot> knots;
  const double quarter = (curve.t_end - curve.t_begin) / 4.0;
  for (int q = 0; q < 4; ++q) {
    const double a = curve.t_begin + q * quarter;
    ArcLengthTable table(curve, a, a + quarter);
    // The last knot of a quadrant is the first of the next one: n-1 new knots per quadrant.
    for (int i = 0; i < per_quadrant - 1; ++i) {
      const double t = table.parameter_at(table.total() * i / (per_quadrant - 1));
      knots.push_back({t, curve.point(t)});
    }
  }
  return knots;
}

std::vector<Knot> equal_arc_knots(const CurveSource& curve, int count) {
  if (count < 2) throw std::invalid_argument("at least 2 knots");
  ArcLengthTable table(curve, curve.t_begin, curve.t_end, 16384);
  std::vector<Knot> knots;
  for (int i = 0; i < count; ++i) {
    const double t = table.parameter_at(table.total() * i / count);
    knots.push_back({t, curve.point(t)});
  }
  return knots;
}

std::vector<Knot> chord_error_knots(const CurveSource& curve, double tolerance) {
  if (!(tolerance > 0)) throw std::invalid_argument("chord tolerance must be > 0");
  ArcLengthTable table(curve, curve.t_begin, curve.t_end, 16384);
  const double total = table.total();
  // Curvature from three points a small arc apart.
  auto curvature_at = [&](double s) {
    const double h = std::min(1e-3 * total, 0.01);
    const Vec3 a = curve.point(table.parameter_at(std::max(0.0, s - h)));
    const Vec3 b = curve.point(table.parameter_at(s));
    const Vec3 c = curve.point(table.parameter_at(std::min(total, s + h)));
    const double ab = (b - a).norm(), bc = (c - b).norm(), ca = (a - c).norm();
    const double area2 = (b - a).cross(c - a).norm();
    return ab * bc * ca > 0 ? 2.0 * area2 / (ab * bc * ca) : 0.0;
  };
  std::vector<Knot> knots;
  double s = 0.0;
  while (s < total - 1e-9) {
    const double t = table.parameter_at(s);
    knots.push_back({t, curve.point(t)});
    // Sagitta of a chord c on radius R: c²/(8R) <= tol  ->  c <= sqrt(8 R tol). Use the largest
    // curvature over the candidate step so a tightening bend ahead is not jumped over.
    double step = total;
    for (int iter = 0; iter < 4; ++iter) {
      double kappa = 0.0;
      for (int k = 0; k <= 8; ++k) kappa = std::max(kappa, curvature_at(std::min(total, s + step * k / 8.0)));
      const double allowed = kappa > 0 ? std::sqrt(8.0 * tolerance / kappa) : total;
      if (allowed >= step) break;
      step = allowed;
    }
    s += std::max(step, 1e-4);
  }
  return knots;
}

}  // namespace drycut::workload
