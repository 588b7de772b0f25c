#include "workload/deviation_reference.hpp"

#include <stdexcept>

namespace drycut::workload {

ReferenceContour::ReferenceContour(const CurveSource& curve, int vertices) {
  if (vertices < 3 || !(curve.t_end > curve.t_begin)) throw std::invalid_argument("reference curve too short");
  vertices_.reserve(static_cast<size_t>(vertices));
  const double dt = (curve.t_end - curve.t_begin) / vertices;
  for (int i = 0; i < vertices; ++i) {
    const Vec3 p = curve.point(curve.t_begin + i * dt);
    vertices_.emplace_back(p.x(), p.y());
  }
  for (size_t i = 0; i < vertices_.size(); ++i) length_ += (vertices_[(i + 1) % vertices_.size()] - vertices_[i]).norm();
  index_.add_polyline(vertices_, true);
  index_.build();
}

ReferenceHit ReferenceContour::nearest(const Vec2& p) const {
  const NearestHit hit = index_.nearest(p);
  const double n = static_cast<double>(vertices_.size());
  double u = (static_cast<double>(hit.segment) + hit.fraction) / n;
  if (u >= 1.0) u -= 1.0;
  return {hit.distance, u};
}

}  // namespace drycut::workload
