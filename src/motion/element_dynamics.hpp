#pragma once
// The machine limits that apply to one path element, after the mode-dependent factors:
// SOFT scales the axis acceleration by SOFT_ACCEL_FACTOR, G0 by G00_ACCEL_FACTOR and the
// jerk by G00_JERK_FACTOR; BRISK has no jerk limit.
#include "interp/geometry/curve.hpp"
#include "interp/path_element.hpp"
#include "machine/machine_profile.hpp"
#include "motion/velocity_ramp.hpp"

namespace drycut::motion {

using geometry::CurvePoint;
using geometry::Vec3;

struct ElementDynamics {
  double length = 0;              // mm
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
  double ovl_factor = 1;
};

ElementDynamics make_element_dynamics(const interp::PathElement& element, double length,
                                      const machine::MachineProfile& profile);

// Tangential acceleration and jerk available at a point: each axis i sees a_t·t_i, so
// a_t <= a_i/|t_i|; on a curved point only (1 - share) of a_i is left for it.
RampLimits tangential_limits(const ElementDynamics& dynamics, const CurvePoint& point);

}  // namespace drycut::motion
