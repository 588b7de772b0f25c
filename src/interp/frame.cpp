#include "interp/frame.hpp"

#include <cmath>

#include <Eigen/Geometry>
#include <Eigen/LU>

#include "interp/geometry/arc_curve.hpp"
#include "interp/geometry/degrees.hpp"
#include "interp/geometry/line_curve.hpp"

namespace drycut::interp {

using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace {

// The rotation about one axis (right-handed), with exact quarter and twelfth turns
// (geometry/degrees.hpp).
Matrix3d axis_rotation(int axis, double angle_deg) {
  const auto [s, c] = geometry::sin_cos_degrees(angle_deg);
  const int i = (axis + 1) % 3, j = (axis + 2) % 3;  // the plane turned: (Y, Z), (Z, X), (X, Y)
  Matrix3d m = Matrix3d::Identity();
  m(i, i) = c;
  m(i, j) = -s;
  m(j, i) = s;
  m(j, j) = c;
  return m;
}

}  // namespace

Frame::Frame(const Matrix3d& linear, const Vector3d& translation)
    : linear_(linear), translation_(translation) {
  pure_translation_ = linear_ == Matrix3d::Identity();
  const double det = linear_.determinant();
  invertible_ = std::isfinite(det) && det != 0.0;
  if (pure_translation_) {
    inverse_ = Matrix3d::Identity();
  } else if (invertible_) {
    inverse_ = linear_.inverse();
  } else {
    inverse_ = Matrix3d::Zero();
  }
}

Frame Frame::translation(const Vector3d& offset) { return Frame(Matrix3d::Identity(), offset); }

Frame Frame::rotation_rpy(const Vector3d& angles_deg) {
  // RPY: about Z first, then about the turned Y', then the twice-turned X'' (intrinsic), which
  // as one matrix acting on inner coordinates is Rz * Ry * Rx.
  return Frame(axis_rotation(2, angles_deg.z()) * axis_rotation(1, angles_deg.y()) *
                   axis_rotation(0, angles_deg.x()),
               Vector3d::Zero());
}

Frame Frame::rotation_about(int axis, double angle_deg) {
  return Frame(axis_rotation(axis, angle_deg), Vector3d::Zero());
}

Frame Frame::scale(const Vector3d& factors) { return Frame(factors.asDiagonal().toDenseMatrix(), Vector3d::Zero()); }

Frame Frame::mirror(const std::array<bool, 3>& axes) {
  Vector3d d(axes[0] ? -1.0 : 1.0, axes[1] ? -1.0 : 1.0, axes[2] ? -1.0 : 1.0);
  return Frame(d.asDiagonal().toDenseMatrix(), Vector3d::Zero());
}

Frame Frame::then(const Frame& inner) const {
  if (pure_translation_ && inner.pure_translation_) return Frame(Matrix3d::Identity(), translation_ + inner.translation_);
  return Frame(linear_ * inner.linear_, linear_ * inner.translation_ + translation_);
}

Vector3d Frame::to_outer(const Vector3d& p) const {
  if (pure_translation_) return p + translation_;
  return linear_ * p + translation_;
}

Vector3d Frame::to_inner(const Vector3d& p) const {
  if (pure_translation_) return p - translation_;
  return inverse_ * (p - translation_);
}

std::optional<geometry::CurvePtr> transform_curve(const geometry::CurvePtr& curve, const Frame& frame) {
  if (frame.is_identity()) return curve;
  if (const auto* arc = dynamic_cast<const geometry::ArcCurve*>(curve.get())) {
    const Vector3d a = frame.vector_to_outer(arc->first_axis());
    const Vector3d b = frame.vector_to_outer(arc->second_axis());
    const Vector3d n = frame.vector_to_outer(arc->normal());
    const double la = a.norm(), lb = b.norm();
    // The circle stays a circle only if its plane is scaled equally in both directions.
    const double tol = 1e-9 * std::max(la, lb);
    if (la <= 0 || std::abs(la - lb) > tol || std::abs(a.dot(b)) > tol * std::max(la, lb)) return std::nullopt;
    const Vector3d e1 = a / la, e2 = b / lb;
    const Vector3d normal = e1.cross(e2);
    // A helix stays a helix only if its axis stays perpendicular to the plane.
    if (arc->axial_travel() != 0.0 && (n - n.dot(normal) * normal).norm() > 1e-9 * std::max(1.0, n.norm()))
      return std::nullopt;
    return std::make_shared<geometry::ArcCurve>(frame.to_outer(arc->centre()), arc->radius() * la, e1, e2,
                                                arc->start_angle(), arc->sweep(), arc->axial_travel() * n.dot(normal));
  }
  if (dynamic_cast<const geometry::LineCurve*>(curve.get()))
    return std::make_shared<geometry::LineCurve>(frame.to_outer(curve->start()), frame.to_outer(curve->end()));
  return std::nullopt;
}

}  // namespace drycut::interp
