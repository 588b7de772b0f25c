#pragma once
// A frame by its components, as programs write settable frames (PGA Job Planning "Frames",
// "Frame components" and "Frame functions"):
//   $P_UIFR[n, X, TR] = 10      coarse translation      $P_UIFR[n, X, FI] = 0.01  fine translation
//   $P_UIFR[n, Z, RT] = 30      rotation (degrees)      $P_UIFR[n, X, SC] = 2     scale factor
//   $P_UIFR[n, X, MI] = 1       mirror                  $P_UIFR[n] = CTRANS(X, 10, Y, 5) (whole)
// The frame they make: the translation (coarse + fine) outermost, then the rotation (RPY about
// X, Y, Z like ROT), the scale, the mirror innermost — the order of the settable frames in the
// profile (frame_chain.cpp) and of TRANS/ROT/SCALE/MIRROR in one frame.
// A whole-frame value arrives from the loader as text "CTRANS(X,10,Y,5):CROT(Z,30)" (parser
// FRAME values; `:` chains them, the product of the frames).
#include <array>
#include <optional>
#include <string>
#include <string_view>

#include <Eigen/Core>

#include "interp/frame.hpp"
#include "machine/machine_profile.hpp"

namespace drycut::interp {

// The function name of drycut's text for a whole frame read from the control:
// CFRAME(l00,l01,l02,l10,l11,l12,l20,l21,l22,tx,ty,tz), the linear part and the translation.
inline constexpr std::string_view kWholeFrameFunction = "CFRAME";

// The RPY angles (degrees) of a rotation matrix r = Rz(c)·Ry(b)·Rx(a), as ROT and $P_..[ax, RT]
// give them: (a, b, c).
Eigen::Vector3d rpy_degrees(const Eigen::Matrix3d& r);

struct FrameComponents {
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  Eigen::Vector3d fine = Eigen::Vector3d::Zero();
  Eigen::Vector3d rotation_deg = Eigen::Vector3d::Zero();
  Eigen::Vector3d scale = Eigen::Vector3d::Ones();
  std::array<bool, 3> mirror{};

  Frame frame() const;
  // Sets component "TR", "FI", "RT", "SC" or "MI" of axis 0..2 (lengths already in mm); false
  // for an unknown component.
  bool set(int axis, std::string_view component, double value);
  // A whole frame from frame functions' text ("CTRANS(X,10,Y,5):CROT(Z,30)"); `unit` converts
  // lengths to mm. Returns an error text, empty on success.
  std::string assign(std::string_view description, double unit);
  // A chain whose order the components cannot hold: the frame is known only as a product.
  bool composed() const { return composed_.has_value(); }
  // The components of a frame known as a product, where it is translation · rotation · scale
  // (no mirror, no shear): none else.
  static std::optional<FrameComponents> of_product(const Frame& frame);
  // The frame functions that make these components, lengths in `unit`:
  // "CTRANS(X,..,Y,..,Z,..):CFINE(..):CROT(..):CSCALE(..):CMIRROR(..)" (assign reads it back).
  std::string text(double unit) const;

 private:
  // One function "CROT(Z,30)"; rank: 0 translation, 1 rotation, 2 scale, 3 mirror.
  std::string assign_function(std::string_view function, double unit, int& rank);
  // A chain whose order the components cannot hold (CROT(..):CTRANS(..)): the product itself.
  std::optional<Frame> composed_;
};

// The components of settable frame `index` in the machine profile (translation and rotation).
FrameComponents profile_frame_components(const machine::MachineProfile& profile, int index);

}  // namespace drycut::interp
