#include "workload/deviation_control_points.hpp"

#include <array>
#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

#include "machine/alarm.hpp"

namespace drycut::workload {

std::vector<ControlPoint> thesis_control_points(const CurveSource& curve) {
  constexpr std::array kThetaDeg{90.0, 100.5, 107.5, 115.0, 127.5, 135.0, 147.5, 155.0, 167.5, 172.0, 180.0};
  std::vector<ControlPoint> points;
  for (size_t i = 0; i < kThetaDeg.size(); ++i) {
    const Vec3 p = curve.point(kThetaDeg[i] * std::numbers::pi / 180.0);
    points.push_back({Vec2(p.x(), p.y()), i == 0});
  }
  return points;
}

std::vector<ControlPoint> read_control_points(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw UsageError("cannot read " + path);
  std::vector<ControlPoint> points;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (line.empty() || line[0] == '#' || std::isalpha(static_cast<unsigned char>(line[0]))) continue;
    std::stringstream fields(line);
    std::string x, y, hold;
    std::getline(fields, x, ',');
    std::getline(fields, y, ',');
    std::getline(fields, hold, ',');
    ControlPoint p;
    try {
      p.nominal = Vec2(std::stod(x), std::stod(y));
    } catch (const std::exception&) {
      throw UsageError(path + ":" + std::to_string(number) + ": need x,y[,hold]");
    }
    hold.erase(0, hold.find_first_not_of(" \t"));
    hold.erase(hold.find_last_not_of(" \t\r") + 1);
    if (hold == "x" || hold == "X") p.hold_x = true;
    else if (!hold.empty() && hold != "y" && hold != "Y")
      throw UsageError(path + ":" + std::to_string(number) + ": hold must be x or y");
    points.push_back(p);
  }
  if (points.empty()) throw UsageError(path + ": no control points");
  return points;
}

std::optional<double> polyline_difference(const std::vector<Vec3>& path, const ControlPoint& point, double window_mm) {
  const int held = point.hold_x ? 0 : 1, free = 1 - held;
  const double target = point.nominal[held];
  std::optional<double> best;
  for (size_t i = 0; i + 1 < path.size(); ++i) {
    const double a = path[i][held] - target, b = path[i + 1][held] - target;
    if (a * b > 0 || a == b) continue;
    const double f = a / (a - b);
    const double diff = path[i][free] + f * (path[i + 1][free] - path[i][free]) - point.nominal[free];
    if (std::abs(diff) <= window_mm && (!best || std::abs(diff) < std::abs(*best))) best = diff;
  }
  return best;
}

std::optional<double> tool_cut_difference(const PolylineIndex& tool_centre, double radius_mm, const ControlPoint& point,
                                          double window_mm) {
  if (tool_centre.segment_count() == 0) return std::nullopt;
  Vec2 along = point.hold_x ? Vec2::UnitY() : Vec2::UnitX();
  // > 0: the point is outside the swept area (material left), < 0: inside it (cut).
  auto gap = [&](double w) { return tool_centre.nearest(point.nominal + w * along).distance - radius_mm; };
  const double g0 = gap(0.0);
  if (g0 == 0.0) return 0.0;
  constexpr double kStep = 0.01;
  double previous[2] = {g0, g0};
  for (int k = 1; k * kStep <= window_mm; ++k) {
    for (int side = 0; side < 2; ++side) {
      const double sign = side == 0 ? 1.0 : -1.0;
      const double w = sign * k * kStep;
      const double g = gap(w);
      if ((g > 0) != (previous[side] > 0)) {
        double lo = w - sign * kStep, hi = w, glo = previous[side];
        for (int iter = 0; iter < 50; ++iter) {
          const double mid = 0.5 * (lo + hi), gm = gap(mid);
          if ((gm > 0) == (glo > 0)) lo = mid, glo = gm;
          else hi = mid;
        }
        return 0.5 * (lo + hi);
      }
      previous[side] = g;
    }
  }
  return std::nullopt;
}

std::optional<double> mean_absolute_error(const std::vector<std::optional<double>>& differences) {
  double sum = 0;
  size_t n = 0;
  for (const auto& d : differences)
    if (d) sum += std::abs(*d), ++n;
  if (n == 0) return std::nullopt;
  return sum / static_cast<double>(n);
}

}  // namespace drycut::workload
