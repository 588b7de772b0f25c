#include "workload/deviation_held_line.hpp"

#include <algorithm>
#include <cmath>

namespace drycut::workload {
namespace {

Vec2 free_direction(const ControlPoint& point) { return point.hold_x ? Vec2::UnitY() : Vec2::UnitX(); }

// First crossing on one side (side = +1 or -1) of the point that is on the part's edge, as the
// signed distance w along the line; nullopt when none lies within range_mm.
std::optional<double> first_cut_crossing(const PolylineIndex& tool_centre, double radius_mm,
                                         const PolylineIndex& programmed, const ControlPoint& point,
                                         double range_mm, double side) {
  constexpr double kMinStep = 1e-3;  // mm: the shortest excursion the walk is sure to see
  const Vec2 e = side * free_direction(point);
  auto gap = [&](double w) { return tool_centre.nearest(point.nominal + w * e).distance - radius_mm; };
  double w = 0.0, g = gap(0.0);
  if (g == 0.0) return 0.0;
  while (w < range_mm) {
    const double w_next = std::min(w + std::max(std::abs(g), kMinStep), range_mm);
    const double g_next = gap(w_next);
    if ((g_next > 0) != (g > 0) || g_next == 0.0) {
      double lo = w, hi = w_next, g_lo = g;
      for (int iter = 0; iter < 60 && hi - lo > 1e-9; ++iter) {
        const double mid = 0.5 * (lo + hi), g_mid = gap(mid);
        if ((g_mid > 0) == (g_lo > 0) && g_mid != 0.0) lo = mid, g_lo = g_mid;
        else hi = mid;
      }
      const double root = 0.5 * (lo + hi);
      if (programmed.nearest(point.nominal + root * e).distance < radius_mm) return side * root;
    }
    w = w_next;
    g = g_next;
  }
  return std::nullopt;
}

}  // namespace

std::optional<double> held_line_polyline_crossing(const PolylineIndex& contour, const ControlPoint& point,
                                                  double range_mm) {
  const Vec2 e = free_direction(point);
  std::optional<double> best;
  for (double t : contour.crossings(point.nominal - range_mm * e, point.nominal + range_mm * e)) {
    const double w = (2.0 * t - 1.0) * range_mm;
    if (!best || std::abs(w) < std::abs(*best)) best = w;
  }
  return best;
}

std::optional<double> held_line_cut_crossing(const PolylineIndex& tool_centre, double radius_mm,
                                             const PolylineIndex& programmed, const ControlPoint& point,
                                             double range_mm) {
  if (tool_centre.segment_count() == 0) return std::nullopt;
  const auto ahead = first_cut_crossing(tool_centre, radius_mm, programmed, point, range_mm, 1.0);
  const auto behind = first_cut_crossing(tool_centre, radius_mm, programmed, point, range_mm, -1.0);
  if (ahead && behind) return std::abs(*ahead) <= std::abs(*behind) ? ahead : behind;
  return ahead ? ahead : behind;
}

}  // namespace drycut::workload
