#include "interp/cutter_compensation_piece.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>

#include "interp/geometry/arc_curve.hpp"
#include "interp/geometry/line_curve.hpp"
#include "interp/geometry/plane.hpp"

namespace drycut::interp {

using geometry::Vec3;

namespace {

// Polyline resolution for the intersection search: the offset turns like its base, so a fixed
// turning angle per segment resolves loops and corners alike.
constexpr double kTurnPerSegment = 0.02;  // rad
constexpr int kMinSegments = 8;
constexpr int kMaxSegments = 4000;
// |n . n_arc| above this: the arc lies in the compensation plane and its offset is an arc.
constexpr double kParallelCosine = 1.0 - 1e-12;

}  // namespace

CompensationPlane CompensationPlane::from_normal_axis(int plane_normal_axis) {
  const geometry::Plane plane = plane_normal_axis == 1   ? geometry::Plane::G18
                                : plane_normal_axis == 0 ? geometry::Plane::G19
                                                         : geometry::Plane::G17;
  const geometry::PlaneAxes axes = geometry::plane_axes(plane);
  return {axes.normal, axes.first, axes.second};
}

OffsetPiece::OffsetPiece(geometry::CurvePtr base, double offset_mm, const CompensationPlane& plane)
    : base_(std::move(base)), offset_(offset_mm), plane_(plane) {
  u_end_ = base_->length();
  straight_ = base_->max_curvature() == 0.0;
  resample();
}

geometry::OffsetDerivatives OffsetPiece::derivatives(double u) const {
  return geometry::offset_derivatives(base_->at(u), offset_, plane_.normal);
}

void OffsetPiece::trim(double u_begin, double u_end) {
  const double length = base_->length();
  u_begin_ = std::clamp(u_begin, 0.0, length);
  u_end_ = std::clamp(u_end, u_begin_, length);
  backwards_.reset();
  resample();
}

void OffsetPiece::resample() {
  const double range = u_end_ - u_begin_;
  int segments = 1;
  if (!straight_) {
    const double turning = range * base_->max_curvature();
    // Clamped as a double: a near-cusp (curvature 1e29) or NaN must not reach the int cast.
    const double wanted = kMinSegments + std::ceil(turning / kTurnPerSegment);
    segments = !(wanted < kMaxSegments) ? kMaxSegments : wanted > kMinSegments ? static_cast<int>(wanted) : kMinSegments;
  }
  sample_u_.resize(static_cast<size_t>(segments) + 1);
  sample_xy_.resize(sample_u_.size());
  for (int i = 0; i <= segments; ++i) {
    const double u = i == segments ? u_end_ : u_begin_ + range * i / segments;
    sample_u_[static_cast<size_t>(i)] = u;
    sample_xy_[static_cast<size_t>(i)] = plane_.project(position(u));
  }
}

bool OffsetPiece::runs_backwards(double u0, double u1) const {
  if (offset_ == 0.0 || straight_ || u1 < u0) return false;
  std::vector<double> probes{u0, 0.5 * (u0 + u1), u1};
  for (double u : sample_u_)
    if (u > u0 && u < u1) probes.push_back(u);
  for (double u : probes) {
    const geometry::CurvePoint b = base_->at(u);
    const Vec3 tangent_in_plane = b.tangent - plane_.normal * plane_.normal.dot(b.tangent);
    const double w2 = tangent_in_plane.squaredNorm();
    if (w2 < 1e-18) continue;  // tangent along the normal: no in-plane direction to compare
    const Vec3 first = geometry::offset_derivatives(b, offset_, plane_.normal).first;
    // Zero means the offset radius vanished (a point), negative that it runs backwards.
    if (first.dot(tangent_in_plane) <= 1e-9 * w2) return true;
  }
  return false;
}

double OffsetPiece::in_plane_length() const {
  double sum = 0.0;
  for (size_t i = 1; i < sample_xy_.size(); ++i) sum += (sample_xy_[i] - sample_xy_[i - 1]).norm();
  return sum;
}

geometry::CurvePtr OffsetPiece::build_curve(geometry::NormalRamp shift) const {
  if (straight_ || u_end_ <= u_begin_)
    return std::make_shared<geometry::LineCurve>(start() + shift.at_begin * plane_.normal,
                                                 end() + shift.at_end * plane_.normal);
  const auto* arc = dynamic_cast<const geometry::ArcCurve*>(base_.get());
  if (arc != nullptr && arc->radius() > 0.0 && std::abs(plane_.normal.dot(arc->normal())) > kParallelCosine) {
    // An arc (or helix) about the plane normal: its offset is the concentric arc with the radius
    // changed by the offset; the angle parameter is shared, so trimming maps linearly, and so
    // does a shift along the normal (it changes the axial travel only).
    const double length = arc->length();
    const Vec3 n_arc = arc->normal();
    const double along = plane_.normal.dot(n_arc);  // +1 or -1
    const Vec3 e1 = (arc->start() - arc->centre()) / arc->radius();
    const Vec3 e2 = n_arc.cross(e1);
    const double turn_sign = arc->sweep() > 0.0 ? 1.0 : -1.0;
    const double radius = arc->radius() - offset_ * turn_sign * along;
    const double f0 = u_begin_ / length, f1 = u_end_ / length;
    double start_angle = arc->sweep() * f0;
    if (radius < 0.0) start_angle += std::numbers::pi;  // the offset point is across the centre
    const Vec3 centre = arc->centre() + arc->axial_travel() * f0 * n_arc + shift.at_begin * plane_.normal;
    const double axial = arc->axial_travel() * (f1 - f0) + (shift.at_end - shift.at_begin) * along;
    return std::make_shared<geometry::ArcCurve>(centre, std::abs(radius), e1, e2, start_angle, arc->sweep() * (f1 - f0),
                                                axial);
  }
  if (shift.at_begin == 0.0 && shift.at_end == 0.0)
    return std::make_shared<geometry::OffsetCurve>(base_, offset_, plane_.normal, u_begin_, u_end_);
  return std::make_shared<geometry::OffsetCurve>(base_, offset_, plane_.normal, u_begin_, u_end_, shift);
}

}  // namespace drycut::interp
