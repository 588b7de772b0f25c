#pragma once
// The experiment's accuracy measure (EXPERIMENT.md §7): at each control point hold one
// coordinate (Y, or X for point 1 at the top of the contour) and take the difference in the other
// coordinate between the contour and the point; the figure of merit is the mean absolute error.
#include <optional>
#include <string>
#include <vector>

#include "workload/curve_source.hpp"
#include "workload/deviation_polyline_index.hpp"

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

// Signed difference (contour minus point) along the free coordinate where the polyline crosses
// the held coordinate, the crossing nearest the point within `window_mm`.
std::optional<double> polyline_difference(const std::vector<Vec3>& path, const ControlPoint& point,
                                          double window_mm = 1.5);

// The same for the surface the tool cuts: the point on the line through the control point where
// the distance to the tool-centre path equals the tool radius (the envelope), nearest the point.
std::optional<double> tool_cut_difference(const PolylineIndex& tool_centre, double radius_mm,
                                          const ControlPoint& point, double window_mm = 1.5);

// Mean of |difference| over the points that have one; nullopt when none has.
std::optional<double> mean_absolute_error(const std::vector<std::optional<double>>& differences);

}  // namespace drycut::workload
