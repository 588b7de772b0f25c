#pragma once
// Polar coordinates (docs/controller-state.md, "Polar coordinates"): a pole in the working plane,
// a polar angle AP= (degrees, from the plane's first axis, counter-clockwise looking against the
// plane normal) and a polar radius RP= (always a length >= 0). All in workpiece coordinates; the
// frame chain maps the resulting point like any programmed point.
//
//   point = pole + RP * (cos AP * first axis + sin AP * second axis), the third coordinate as
//   programmed (cylinder coordinates).
// The pole: G110 relative to the last programmed position, G111 relative to the workpiece zero,
// G112 relative to the last pole; written as plane coordinates or itself in AP=/RP= about that
// reference. No pole defined: the workpiece zero. AP is kept until a new pole or plane, RP until
// a new RP.
#include <optional>

#include <Eigen/Core>

namespace drycut::interp {

// Indices 0 = X, 1 = Y, 2 = Z of a plane's axes: G17 (X, Y, Z), G18 (Z, X, Y), G19 (Y, Z, X).
struct PlaneIndices {
  int first;
  int second;
  int normal;
};

enum class PoleReference { LastPosition /*G110*/, WorkpieceZero /*G111*/, LastPole /*G112*/ };

// The polar words of one block, converted to mm and degrees.
struct PolarWords {
  std::optional<double> angle_deg;   // AP=
  bool angle_incremental = false;    // AP=IC(..): added to the stored angle
  std::optional<double> radius_mm;   // RP=
  bool any() const { return angle_deg || radius_mm; }
};

// The plane coordinates written in a pole block (X/Y for G17 ...), already in mm.
struct PoleWords {
  std::optional<double> first;
  std::optional<double> second;
};

class PolarState {
 public:
  const Eigen::Vector3d& pole() const { return pole_; }
  double angle_deg() const { return angle_deg_; }
  double radius_mm() const { return radius_mm_; }

  // G110/G111/G112: a new pole from Cartesian words or (if `polar.any()`) polar words about the
  // reference point; the stored angle starts again at 0. `last_position` is the current
  // programmed position in workpiece coordinates.
  void define_pole(PoleReference reference, const PoleWords& cartesian, const PolarWords& polar,
                   const PlaneIndices& plane, const Eigen::Vector3d& last_position);
  // A motion block's AP=/RP=: updates the stored values and returns the end point; coordinates
  // outside the plane come from `base` (the block's Cartesian target).
  Eigen::Vector3d target(const PolarWords& words, const PlaneIndices& plane, const Eigen::Vector3d& base);
  // G17/G18/G19 changed: the angle is forgotten.
  void plane_changed() { angle_deg_ = 0.0; }

 private:
  Eigen::Vector3d pole_ = Eigen::Vector3d::Zero();
  double angle_deg_ = 0.0;
  double radius_mm_ = 0.0;
};

}  // namespace drycut::interp
