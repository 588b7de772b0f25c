#pragma once
// Working planes G17/G18/G19 and their right-handed axis triples. A positive angle in a plane is
// counter-clockwise when looking against the normal (from +normal down onto the plane), so G3 is
// a positive sweep and G2 a negative one in every plane.
#include <Eigen/Core>

namespace drycut::geometry {

enum class Plane { G17, G18, G19 };

struct PlaneAxes {
  Eigen::Vector3d first;   // 1st plane axis (abscissa)
  Eigen::Vector3d second;  // 2nd plane axis (ordinate)
  Eigen::Vector3d normal;  // infeed / helix axis; first x second == normal
};

// G17: (X, Y) normal +Z; G18: (Z, X) normal +Y; G19: (Y, Z) normal +X.
inline PlaneAxes plane_axes(Plane plane) {
  switch (plane) {
    case Plane::G18: return {Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY()};
    case Plane::G19: return {Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitX()};
    case Plane::G17: break;
  }
  return {Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ()};
}

}  // namespace drycut::geometry
