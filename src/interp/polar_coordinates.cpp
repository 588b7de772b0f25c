#include "interp/polar_coordinates.hpp"

#include <cmath>

#include "interp/geometry/degrees.hpp"

namespace drycut::interp {

using Eigen::Vector3d;

namespace {

Vector3d polar_offset(double angle_deg, double radius, const PlaneIndices& plane) {
  const auto [s, c] = geometry::sin_cos_degrees(angle_deg);  // AP=90: exactly on the axis
  Vector3d v = Vector3d::Zero();
  v[plane.first] = radius * c;
  v[plane.second] = radius * s;
  return v;
}

}  // namespace

void PolarState::define_pole(PoleReference reference, const PoleWords& cartesian, const PolarWords& polar,
                             const PlaneIndices& plane, const Vector3d& last_position) {
  Vector3d origin = Vector3d::Zero();
  if (reference == PoleReference::LastPosition) origin = last_position;
  if (reference == PoleReference::LastPole) origin = pole_;
  Vector3d pole = pole_;
  if (polar.any()) {
    // A pole in polar form: angle and radius about the reference (AP=IC would be relative to
    // the stored angle like in a motion block).
    double angle = polar.angle_deg.value_or(0.0);
    if (polar.angle_incremental) angle += angle_deg_;
    const Vector3d p = origin + polar_offset(angle, polar.radius_mm.value_or(0.0), plane);
    pole[plane.first] = p[plane.first];
    pole[plane.second] = p[plane.second];
  } else {
    pole[plane.first] = origin[plane.first] + cartesian.first.value_or(0.0);
    pole[plane.second] = origin[plane.second] + cartesian.second.value_or(0.0);
  }
  pole_ = pole;
  angle_deg_ = 0.0;
}

Vector3d PolarState::target(const PolarWords& words, const PlaneIndices& plane, const Vector3d& base) {
  if (words.angle_deg) angle_deg_ = words.angle_incremental ? angle_deg_ + *words.angle_deg : *words.angle_deg;
  if (words.radius_mm) radius_mm_ = *words.radius_mm;
  Vector3d p = base;
  const Vector3d offset = polar_offset(angle_deg_, radius_mm_, plane);
  p[plane.first] = pole_[plane.first] + offset[plane.first];
  p[plane.second] = pole_[plane.second] + offset[plane.second];
  return p;
}

}  // namespace drycut::interp
