#include "app/curve_options.hpp"

#include <cmath>
#include <fstream>
#include <map>
#include <memory>
#include <numbers>
#include <sstream>

#include "machine/alarm.hpp"
#include "parser/expression_api.hpp"

namespace drycut::app {
namespace {

constexpr double kDegPerRad = 180.0 / std::numbers::pi;

// NC expressions take angles in degrees, so the curve parameter is handed to them in degrees:
// "18+4*COS(6*T)*COS(2*T)" is the thesis contour with T the polar angle in degrees.
std::function<double(double)> expression_of_t(const std::string& text) {
  // Evaluate once up front so a bad expression fails before any knot is computed.
  parser::evaluate_expression(text, {{"T", 0.0}});
  return [text](double t_rad) { return parser::evaluate_expression(text, {{"T", t_rad * kDegPerRad}}); };
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> parts;
  std::stringstream in(s);
  for (std::string part; std::getline(in, part, sep);) parts.push_back(part);
  return parts;
}

workload::CurveSource polyline_curve(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw UsageError("cannot read " + path);
  auto points = std::make_shared<std::vector<workload::Vec3>>();
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (line.empty() || line[0] == '#' || std::isalpha(static_cast<unsigned char>(line[0]))) continue;
    auto fields = split(line, ',');
    if (fields.size() < 2) throw UsageError(path + ":" + std::to_string(number) + ": need x,y[,z]");
    try {
      points->emplace_back(std::stod(fields[0]), std::stod(fields[1]), fields.size() > 2 ? std::stod(fields[2]) : 0.0);
    } catch (const std::exception&) {
      throw UsageError(path + ":" + std::to_string(number) + ": not a number");
    }
  }
  if (points->size() < 3) throw UsageError(path + ": at least 3 points are needed");
  // A closed polyline through the points, parameter = point index (wrapping to the first).
  workload::CurveSource c;
  c.t_begin = 0.0;
  c.t_end = static_cast<double>(points->size());
  c.point = [points](double t) {
    const double n = static_cast<double>(points->size());
    t = std::fmod(std::fmod(t, n) + n, n);
    const size_t i = static_cast<size_t>(t);
    const double f = t - static_cast<double>(i);
    return workload::Vec3((1 - f) * (*points)[i] + f * (*points)[(i + 1) % points->size()]);
  };
  return c;
}

}  // namespace

void add_curve_options(CLI::App& cmd, CurveOptions& options) {
  cmd.add_option("--polar", options.polar, "Polar curve r(T), T = polar angle in degrees")->group("Curve");
  cmd.add_option("--parametric", options.parametric, "Parametric curve \"x(T);y(T)[;z(T)]\", T in degrees 0..360")
      ->group("Curve");
  cmd.add_option("--points", options.points_csv, "CSV of measured points x,y[,z] (closed polyline)")->group("Curve");
}

workload::CurveSource make_curve(const CurveOptions& options) {
  const int given = !options.polar.empty() + !options.parametric.empty() + !options.points_csv.empty();
  if (given > 1) throw UsageError("give only one of --polar, --parametric, --points");
  if (!options.points_csv.empty()) return polyline_curve(options.points_csv);
  if (!options.parametric.empty()) {
    auto parts = split(options.parametric, ';');
    if (parts.size() < 2 || parts.size() > 3) throw UsageError("--parametric needs \"x(T);y(T)[;z(T)]\"");
    std::vector<std::function<double(double)>> f;
    for (const auto& p : parts) f.push_back(expression_of_t(p));
    workload::CurveSource c;
    c.t_begin = 0.0;
    c.t_end = 2.0 * std::numbers::pi;
    c.point = [f](double t) { return workload::Vec3(f[0](t), f[1](t), f.size() > 2 ? f[2](t) : 0.0); };
    return c;
  }
  if (!options.polar.empty()) return workload::polar_curve(expression_of_t(options.polar));
  return workload::polar_curve(workload::thesis_radius);
}

}  // namespace drycut::app
