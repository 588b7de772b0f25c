#include "interp/geometry/line_curve.hpp"

#include <algorithm>

namespace drycut::geometry {

LineCurve::LineCurve(Vec3 a, Vec3 b) : a_(std::move(a)), b_(std::move(b)) {
  const Vec3 d = b_ - a_;
  length_ = d.norm();
  // A fixed direction for a zero-length move keeps downstream code free of NaN checks.
  direction_ = length_ > 0.0 ? Vec3(d / length_) : Vec3(Vec3::UnitX());
}

CurvePoint LineCurve::at(double s) const {
  s = std::clamp(s, 0.0, length_);
  CurvePoint p;
  // Interpolate towards b from whichever end is nearer so that at(length()) is exactly b.
  p.position = s <= 0.5 * length_ ? Vec3(a_ + s * direction_) : Vec3(b_ - (length_ - s) * direction_);
  p.tangent = direction_;
  return p;
}

}  // namespace drycut::geometry
