#pragma once
// A curve moved by a constant vector, and translate_curve, which moves any curve: a line or a
// circle/helix stays a LineCurve/ArcCurve (the compensation and the planner keep their closed
// forms), any other curve becomes a TranslatedCurve that evaluates its base and adds the shift.
// Used for the reference point of turning tools under tool radius compensation
// (interp/cutter_compensation_edge_reference.hpp).
#include "interp/geometry/curve.hpp"

namespace drycut::geometry {

class TranslatedCurve final : public Curve {
 public:
  TranslatedCurve(CurvePtr base, Vec3 shift);

  double length() const override { return base_->length(); }
  CurvePoint at(double s) const override;
  Vec3 start() const override { return base_->start() + shift_; }
  Vec3 end() const override { return base_->end() + shift_; }
  double max_curvature() const override { return base_->max_curvature(); }

 private:
  CurvePtr base_;
  Vec3 shift_;
};

// `curve` moved by `shift`.
CurvePtr translate_curve(const CurvePtr& curve, const Vec3& shift);

}  // namespace drycut::geometry
