#pragma once
// The machine limits that apply to one path element, after the mode-dependent factors:
// SOFT scales the axis acceleration by SOFT_ACCEL_FACTOR, G0 by G00_ACCEL_FACTOR and the
// jerk by G00_JERK_FACTOR; BRISK has no jerk limit.
#include <vector>

#include "interp/geometry/curve.hpp"
#include "interp/path_element.hpp"
#include "machine/machine_profile.hpp"
#include "motion/velocity_ramp.hpp"

namespace drycut::motion {

using geometry::CurvePoint;
using geometry::Vec3;

// A synchronized extra axis (rotary A/B/C, linear U/V/W) moving with the element: its share of
// the path velocity (travel / path length: constant, it is interpolated linearly) and limits.
struct ExtraAxisTerm {
  int axis = 0;                   // index into MachineProfile::extra_axes
  double tangent = 0;             // d(axis)/ds
  double velocity = 0;            // MAX_AX_VELO
  double accel = 0;               // usable acceleration in this mode
  double jerk = 0;                // usable jerk in this mode
  double raw_accel = 0;           // MAX_AX_ACCEL (overload rule)
  double transition_jerk = 0;     // PATH_TRANS_JERK_LIM
  double compress_tol = 0.1;      // MD33100 COMPRESS_POS_TOL: how far a compressor's fit may leave the axis's course
};

struct ElementDynamics {
  double length = 0;              // path length (mm; with grouped extra axes their units count too)
  double feed = 0;                // programmed F in mm/s (0 for rapid)
  bool rapid = false;
  bool soft = false;              // jerk-limited profile
  Vec3 axis_velocity = Vec3::Zero();   // MAX_AX_VELO
  Vec3 axis_accel = Vec3::Zero();      // usable axis acceleration in this mode
  Vec3 axis_jerk = Vec3::Zero();       // usable axis jerk in this mode
  Vec3 raw_axis_accel = Vec3::Zero();  // MAX_AX_ACCEL (overload rule)
  Vec3 transition_jerk = Vec3::Zero(); // PATH_TRANS_JERK_LIM (SOFT transitions)
  double path_jerk = 0;           // MAX_PATH_JERK in this mode
  double centripetal_share = 0;   // CURV_EFFECT_ON_PATH_ACCEL
  double ipo_cycle = 0;
  double short_block_factor = 0;
  bool inserted = false;          // control-inserted element: no short-block limit
  // The length the short-block rule sees: the programmed block's (a neighbour the corner
  // smoothing trimmed is still one block on the control), else `length`.
  double block_length = 0;
  double ovl_factor = 1;
  // Extra axes: the geometry's arc length per unit of path length (1 unless extra axes count in
  // the path length, FGROUP) and each moving extra axis.
  double geometry_scale = 1;
  std::vector<ExtraAxisTerm> extra;
};

ElementDynamics make_element_dynamics(const interp::PathElement& element, double length,
                                      const machine::MachineProfile& profile);

// Tangential acceleration and jerk available at a point: each axis i sees a_t·t_i, so
// a_t <= a_i/|t_i|; on a curved point only (1 - share) of a_i is left for it.
RampLimits tangential_limits(const ElementDynamics& dynamics, const CurvePoint& point);

// The point at path length s: the curve's point at s·geometry_scale with its derivatives taken
// per unit of path length (tangent × scale, curvature × scale², its rate × scale³).
CurvePoint path_point(const ElementDynamics& dynamics, const geometry::Curve& curve, double s);

// The curve seen along the path parameter (path_point), for code that walks a Curve.
class PathParameterCurve : public geometry::Curve {
 public:
  PathParameterCurve(const geometry::Curve& curve, const ElementDynamics& dynamics, double path_length)
      : curve_(curve), dynamics_(dynamics), length_(path_length) {}
  double length() const override { return length_; }
  CurvePoint at(double s) const override { return path_point(dynamics_, curve_, s); }
  double max_curvature() const override { return curve_.max_curvature(); }

 private:
  const geometry::Curve& curve_;
  const ElementDynamics& dynamics_;
  double length_;
};

}  // namespace drycut::motion
