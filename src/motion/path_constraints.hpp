#pragma once
// The velocity limits, separate from the solver that combines them (a new limit is a new
// constraint class added to the planner's list, not an edit of the passes).
//  - PointConstraint: a bound on the path velocity at one point of an element.
//  - JunctionConstraint: a bound at the transition between two consecutive elements.
#include <memory>
#include <vector>

#include "interp/path_element.hpp"
#include "motion/element_dynamics.hpp"
#include "motion/limit.hpp"

namespace drycut::motion {

struct VelocityBound {
  double velocity = std::numeric_limits<double>::infinity();
  Limit limit = Limit::Feed;

  void tighten(double v, Limit l) {
    if (v < velocity) {
      velocity = v;
      limit = l;
    }
  }
};

class PointConstraint {
 public:
  virtual ~PointConstraint() = default;
  virtual Limit limit() const = 0;
  // Upper bound on the path velocity at `point` (infinity when not binding).
  virtual double max_velocity(const ElementDynamics& dynamics, const CurvePoint& point) const = 0;
};

// Both sides of a block transition.
struct Junction {
  const interp::PathElement& before;
  const ElementDynamics& before_dynamics;
  const CurvePoint& before_end;
  const interp::PathElement& after;
  const ElementDynamics& after_dynamics;
  const CurvePoint& after_start;
};

class JunctionConstraint {
 public:
  virtual ~JunctionConstraint() = default;
  virtual Limit limit() const = 0;
  virtual double max_velocity(const Junction& junction) const = 0;
};

// Programmed F (or, for G0, the rapid velocity: each axis at most its MAX_AX_VELO).
class FeedConstraint : public PointConstraint {
 public:
  Limit limit() const override { return Limit::Feed; }
  double max_velocity(const ElementDynamics& d, const CurvePoint& p) const override;
};
// Each axis i moves at v·|t_i| <= MAX_AX_VELO_i (for G0 this is reported as the feed bound).
class AxisVelocityConstraint : public PointConstraint {
 public:
  Limit limit() const override { return Limit::Axis; }
  double max_velocity(const ElementDynamics& d, const CurvePoint& p) const override;
};
// Centripetal acceleration v²·|κ_i| <= share · a_i (share 1 when the profile gives 0).
class CurvatureConstraint : public PointConstraint {
 public:
  Limit limit() const override { return Limit::Curvature; }
  double max_velocity(const ElementDynamics& d, const CurvePoint& p) const override;
};
// SOFT only: at constant path speed the axis jerk is v³·(d³P/ds³)_i <= j_i.
class CurvatureJerkConstraint : public PointConstraint {
 public:
  Limit limit() const override { return Limit::Jerk; }
  double max_velocity(const ElementDynamics& d, const CurvePoint& p) const override;
};
// The block must last at least one IPO cycle with margin: v <= factor · L / T_IPO.
class ShortBlockConstraint : public PointConstraint {
 public:
  Limit limit() const override { return Limit::ShortBlock; }
  double max_velocity(const ElementDynamics& d, const CurvePoint& p) const override;
};

// G60 / G9: the element before the transition ends at rest.
class ExactStopConstraint : public JunctionConstraint {
 public:
  Limit limit() const override { return Limit::ExactStop; }
  double max_velocity(const Junction& j) const override;
};
// G64 overload rule: each axis velocity may jump by at most a_i·(OVL - 1)·T_IPO.
class CornerConstraint : public JunctionConstraint {
 public:
  Limit limit() const override { return Limit::Corner; }
  double max_velocity(const Junction& j) const override;
};

// SOFT transitions (PATH_TRANS_JERK_LIM, facts §2.2 and "jerk limitation along the path through
// velocity reduction"): the control passes a block transition within one IPO cycle T, so a jump
// of an axis velocity by Δv_i is an acceleration pulse Δv_i/T that rises and falls within T
// (jerk Δv_i/T²), and a jump of the centripetal acceleration v²·Δκ_i is an acceleration step
// within T (jerk v²·Δκ_i/T). Both must stay within the transition jerk J_i:
//   |v·Δt_i| <= J_i·T²   and   v²·|Δκ_i| <= J_i·T.
// Reported as a corner (tangent jump) or as jerk (curvature jump only, e.g. Akima knots).
class TransitionJerkConstraint : public JunctionConstraint {
 public:
  Limit limit() const override { return Limit::Corner; }
  double max_velocity(const Junction& j) const override;
};
class CurvatureStepConstraint : public JunctionConstraint {
 public:
  Limit limit() const override { return Limit::Jerk; }
  double max_velocity(const Junction& j) const override;
};

std::vector<std::unique_ptr<PointConstraint>> default_point_constraints();
std::vector<std::unique_ptr<JunctionConstraint>> default_junction_constraints();

// True when the element demands standstill at its end (G60 or G9).
bool ends_in_exact_stop(const interp::PathElement& element);

}  // namespace drycut::motion
