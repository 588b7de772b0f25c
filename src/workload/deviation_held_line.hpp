#pragma once
// Where a control point's held line meets a contour (EXPERIMENT.md §7, the microscope): the line
// through the point along its free coordinate (Y held: the line y = y_p, the difference in X;
// X held: the line x = x_p, the difference in Y), searched over `range_mm` on either side of the
// point. The crossing closest to the point gives the signed difference contour minus point; no
// crossing within the range is an answer of its own (nullopt), which the caller counts and
// reports - never dropped silently.
//
// Programmed contour: the sampled path as a polyline; the crossings of the held segment
// [point - range, point + range] come from the polyline index (cells under the segment only).
//
// Cut contour: the edge of the area the tool sweeps, {p : dist(p, tool-centre path) = R}. Along
// the line the gap g(w) = dist(point + w e, path) - R is 1-Lipschitz in w, so no crossing lies
// closer than |g| to w: the search walks outwards on each side in steps of max(|g|, 1 um) and
// bisects where g changes sign (only a dip into the swept area shorter than 1 um can be missed).
// The swept band has two edges: the part's surface along the programmed contour and the far
// edge 2R out, in air. A crossing counts only when it lies within R of the programmed contour.
#include <optional>

#include "workload/deviation_control_points.hpp"
#include "workload/deviation_polyline_index.hpp"

namespace drycut::workload {

// Signed difference (contour minus point) along the held line to the closest crossing of the
// indexed polyline within `range_mm`; nullopt when the line does not meet it there.
std::optional<double> held_line_polyline_crossing(const PolylineIndex& contour, const ControlPoint& point,
                                                  double range_mm);

// The same for the surface the tool cuts: `tool_centre` indexed tool-centre path, `radius_mm`
// the tool radius, `programmed` the programmed contour that tells the part's edge from the far one.
std::optional<double> held_line_cut_crossing(const PolylineIndex& tool_centre, double radius_mm,
                                             const PolylineIndex& programmed, const ControlPoint& point,
                                             double range_mm);

}  // namespace drycut::workload
