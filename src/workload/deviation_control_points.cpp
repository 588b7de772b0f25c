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

ControlPointMae control_point_mae(const std::vector<std::optional<double>>& differences) {
  ControlPointMae result;
  result.points = differences.size();
  double sum = 0;
  for (const auto& d : differences)
    if (d) sum += std::abs(*d), ++result.measured;
  result.without_crossing = result.points - result.measured;
  if (result.measured) result.mae_mm = sum / static_cast<double>(result.measured);
  return result;
}

}  // namespace drycut::workload
