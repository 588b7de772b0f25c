#include "interp/contour_recording.hpp"

#include <cmath>
#include <numbers>

#include "interp/geometry/arc_curve.hpp"

namespace drycut::interp {

void ContourRecorder::consume(PathElement&& element) {
  // Only motion makes contour: dwells, stops and mode changes between the blocks do not.
  if (!element.curve || (element.kind != ElementKind::Line && element.kind != ElementKind::Arc &&
                         element.kind != ElementKind::SplineSpan))
    return;
  RecordedContourElement r;
  r.rapid = element.rapid;
  const geometry::Curve& c = *element.curve;
  r.start = to_workpiece_(c.start());
  r.end = to_workpiece_(c.end());
  r.quarter = to_workpiece_(c.at(0.25 * c.length()).position);
  if (const auto* arc = dynamic_cast<const geometry::ArcCurve*>(&c)) {
    r.arc = true;
    r.centre = to_workpiece_(arc->centre());
    r.sweep_deg = std::abs(arc->sweep()) * 180.0 / std::numbers::pi;
  } else {
    r.centre = geometry::Vec3::Zero();
  }
  elements_.push_back(r);
}

std::optional<double> ContourRecorder::value(size_t i, int k, const PlaneIndices& plane) const {
  if (i >= elements_.size() || k < 0 || k >= kColumns) return std::nullopt;
  const RecordedContourElement& e = elements_[i];
  const auto a = [&](const geometry::Vec3& p) { return p[plane.first]; };
  const auto o = [&](const geometry::Vec3& p) { return p[plane.second]; };
  // Counter-clockwise in (abscissa, ordinate) is G3 in every plane (G17 X-Y, G18 Z-X, G19 Y-Z
  // are right-handed about their normal): the turn from the start to a quarter along the arc
  // (also for a whole circle).
  const bool counter_clockwise = (a(e.start) - a(e.centre)) * (o(e.quarter) - o(e.centre)) -
                                     (o(e.start) - o(e.centre)) * (a(e.quarter) - a(e.centre)) >
                                 0;
  switch (k) {
    case 0:
      if (!e.arc) return e.rapid ? 0.0 : 1.0;
      return counter_clockwise ? 3.0 : 2.0;
    case 1: return a(e.start);
    case 2: return o(e.start);
    case 3: return a(e.end);
    case 4: return o(e.end);
    case 5: return e.arc ? a(e.centre) : 0.0;
    case 6: return e.arc ? o(e.centre) : 0.0;
    case 7: return e.arc ? (counter_clockwise ? e.sweep_deg : -e.sweep_deg) : 0.0;
    default: return e.arc ? std::hypot(a(e.start) - a(e.centre), o(e.start) - o(e.centre)) : 0.0;
  }
}

}  // namespace drycut::interp
