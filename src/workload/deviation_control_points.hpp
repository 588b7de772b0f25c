#pragma once
// The experiment's accuracy measure (EXPERIMENT.md §7): at each control point hold one
// coordinate (Y, or X for point 1 at the top of the contour) and take the difference in the other
// coordinate between the contour and the point; the figure of merit is the mean absolute error.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "workload/curve_source.hpp"
#include "workload/deviation_polyline_index.hpp"  // Vec2

namespace drycut::workload {

struct ControlPoint {
  Vec2 nominal = Vec2::Zero();
  bool hold_x = false;  // true: hold X, difference in Y
};

// The eleven points of the second quadrant, at the thesis's polar angles, on `curve` (whose
// parameter must be the polar angle in radians, as for polar_curve()).
std::vector<ControlPoint> thesis_control_points(const CurveSource& curve);

// CSV lines "x,y[,hold]" with hold "x" or "y" (default y); '#' lines and a header are skipped.
// Throws UsageError.
std::vector<ControlPoint> read_control_points(const std::string& path);

// The figure of merit over the points whose held line meets the contour (differences from
// deviation_held_line.hpp), with the count of those it does not meet, which the MAE leaves out.
struct ControlPointMae {
  std::optional<double> mae_mm;  // nullopt when no point has a crossing
  size_t points = 0, measured = 0, without_crossing = 0;
};
ControlPointMae control_point_mae(const std::vector<std::optional<double>>& differences);

}  // namespace drycut::workload
