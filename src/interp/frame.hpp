#pragma once
// One SINUMERIK frame: the rule that takes coordinates of an inner coordinate system (the one a
// program speaks in) to the outer one, as an affine map  outer = linear * inner + translation.
// Translation, rotation, scale and mirror all become this one form, so chaining frames is a
// product and every point, vector and curve goes through the same two lines of arithmetic.
//
// Factories follow the NC instructions (docs/controller-state.md, "Frames"):
//   translation(v)        TRANS / CTRANS: the inner origin sits at v in the outer system
//   rotation_rpy(a)       ROT X.. Y.. Z..: RPY angles in degrees, turned about Z, then the new Y',
//                         then the new X'' (Basic Functions manual K2, frames): R = Rz * Ry * Rx
//   rotation_about(i, a)  ROT RPL= (about the plane normal) / CROT with one axis
//   scale(f)              SCALE: inner lengths are multiplied by f per axis
//   mirror(m)             MIRROR X0: the direction of the axis is reversed
// `a.then(b)` is the frame a followed by b inside it (the additive instructions: ATRANS after
// AROT translates along the rotated axes, ASCALE scales what follows).
#include <array>
#include <optional>

#include <Eigen/Core>

#include "interp/geometry/curve.hpp"

namespace drycut::interp {

class Frame {
 public:
  Frame() = default;
  static Frame translation(const Eigen::Vector3d& offset);
  static Frame rotation_rpy(const Eigen::Vector3d& angles_deg);
  static Frame rotation_about(int axis, double angle_deg);
  static Frame scale(const Eigen::Vector3d& factors);
  static Frame mirror(const std::array<bool, 3>& axes);
  // Any frame by its linear part and translation (p -> linear·p + translation).
  static Frame affine(const Eigen::Matrix3d& linear, const Eigen::Vector3d& translation) { return Frame(linear, translation); }

  // This frame with `inner` chained inside it: (a.then(b))(p) = a(b(p)).
  Frame then(const Frame& inner) const;

  Eigen::Vector3d to_outer(const Eigen::Vector3d& p) const;
  Eigen::Vector3d to_inner(const Eigen::Vector3d& p) const;
  // Directions (no translation).
  Eigen::Vector3d vector_to_outer(const Eigen::Vector3d& v) const { return linear_ * v; }
  Eigen::Vector3d vector_to_inner(const Eigen::Vector3d& v) const { return inverse_ * v; }

  const Eigen::Matrix3d& linear() const { return linear_; }
  const Eigen::Vector3d& offset() const { return translation_; }
  // No rotation, scale or mirror: points only shift (the fast and exact common case).
  bool is_pure_translation() const { return pure_translation_; }
  bool is_identity() const { return pure_translation_ && translation_.isZero(0.0); }
  // A linear part that is singular (SCALE X0) has no inverse: such a frame is refused.
  bool invertible() const { return invertible_; }

 private:
  Frame(const Eigen::Matrix3d& linear, const Eigen::Vector3d& translation);

  Eigen::Matrix3d linear_ = Eigen::Matrix3d::Identity();
  Eigen::Matrix3d inverse_ = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation_ = Eigen::Vector3d::Zero();
  bool pure_translation_ = true;
  bool invertible_ = true;
};

// A curve given in the inner system of `frame`, in the outer system. Lines map end to end. A
// circle stays a circle when the frame scales its plane equally in both directions and keeps the
// plane's normal perpendicular to it (any rotation, mirror, uniform scale); otherwise nullopt (an
// unequal scale would make an ellipse). A mirror reverses the sense of rotation by itself: the
// circle's axes are mapped, so a G2 drawn in the mirrored system runs as G3 in the outer one.
std::optional<geometry::CurvePtr> transform_curve(const geometry::CurvePtr& curve, const Frame& frame);

}  // namespace drycut::interp
