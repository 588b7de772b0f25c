#include "parser/circle_data.hpp"

#include <cmath>

namespace drycut::parser {
namespace {

std::optional<std::array<double, 2>> circumcentre(const std::array<double, 2>& p1, const std::array<double, 2>& p2,
                                                  const std::array<double, 2>& p3) {
  const double ax = p2[0] - p1[0], ay = p2[1] - p1[1];
  const double bx = p3[0] - p1[0], by = p3[1] - p1[1];
  const double a2 = ax * ax + ay * ay, b2 = bx * bx + by * by;
  const double d = 2.0 * (ax * by - ay * bx);
  // Collinear within the rounding of the coordinates: |d| is twice the triangle's area.
  if (!(std::fabs(d) > 1e-12 * (a2 + b2))) return std::nullopt;
  return std::array<double, 2>{p1[0] + (by * a2 - ay * b2) / d, p1[1] + (ax * b2 - bx * a2) / d};
}

}  // namespace

std::optional<CircleData> circle_through_points(std::span<const std::array<double, 2>> points) {
  if (points.size() != 3 && points.size() != 4) return std::nullopt;
  double sx = 0.0, sy = 0.0;
  int circles = 0;
  const size_t n = points.size();
  // Every triple of the points: one for three points, four for four.
  for (size_t skip = 0; skip < (n == 4 ? 4u : 1u); ++skip) {
    std::array<std::array<double, 2>, 3> t{};
    size_t k = 0;
    for (size_t i = 0; i < n; ++i)
      if (n == 3 || i != skip) t[k++] = points[i];
    if (const auto c = circumcentre(t[0], t[1], t[2])) {
      sx += (*c)[0];
      sy += (*c)[1];
      ++circles;
    }
  }
  if (circles == 0) return std::nullopt;
  CircleData out{sx / circles, sy / circles, 0.0};
  for (const auto& p : points) out.radius += std::hypot(p[0] - out.centre_x, p[1] - out.centre_y);
  out.radius /= static_cast<double>(n);
  return out;
}

}  // namespace drycut::parser
