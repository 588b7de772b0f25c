#pragma once
// A piece [s0, s1] (arc length) of another curve, and trim_curve, which cuts any curve: a line
// or a circle/helix stays a LineCurve/ArcCurve (the planner keeps their closed forms), any other
// curve (spline span, offset curve) becomes a TrimmedCurve that evaluates its base at s0 + s.
// Used by the corner smoothing (interp/corner_smoothing.hpp) to cut the neighbours of a corner.
#include "interp/geometry/curve.hpp"

namespace drycut::geometry {

class TrimmedCurve final : public Curve {
 public:
  TrimmedCurve(CurvePtr base, double s0, double s1);

  double length() const override { return s1_ - s0_; }
  CurvePoint at(double s) const override;
  Vec3 start() const override { return start_; }
  Vec3 end() const override { return end_; }
  double max_curvature() const override { return base_->max_curvature(); }

  const CurvePtr& base() const { return base_; }
  double base_start() const { return s0_; }

 private:
  CurvePtr base_;
  double s0_, s1_;
  Vec3 start_, end_;
};

// The piece [s0, s1] of `curve` (0 <= s0 < s1 <= length).
CurvePtr trim_curve(const CurvePtr& curve, double s0, double s1);

}  // namespace drycut::geometry
