#pragma once
// The true curve as a dense closed polyline in XY with a nearest-point index. Each vertex has
// its parameter fraction u in [0, 1) along the curve; u of the nearest point tells where on the
// contour a path sample is, which is how passes are split at the seam (u = 0).
#include <vector>

#include "workload/curve_source.hpp"
#include "workload/deviation_polyline_index.hpp"

namespace drycut::workload {

struct ReferenceHit {
  double distance = 0.0;  // normal distance to the curve in XY (mm)
  double u = 0.0;         // parameter fraction of the nearest point, [0, 1)
};

class ReferenceContour {
 public:
  // `vertices` points at equal parameter steps; 32768 keep the chord error of the thesis
  // contour below 1e-5 mm.
  explicit ReferenceContour(const CurveSource& curve, int vertices = 32768);
  ReferenceHit nearest(const Vec2& p) const;
  const std::vector<Vec2>& vertices() const { return vertices_; }
  double u_of_vertex(size_t i) const { return static_cast<double>(i) / static_cast<double>(vertices_.size()); }
  double length() const { return length_; }

 private:
  std::vector<Vec2> vertices_;
  PolylineIndex index_;
  double length_ = 0.0;
};

}  // namespace drycut::workload
