#pragma once
// Straight segment from a to b (G0/G1). A zero-length segment is allowed: its tangent is +X.
#include "interp/geometry/curve.hpp"

namespace drycut::geometry {

class LineCurve final : public Curve {
 public:
  LineCurve(Vec3 a, Vec3 b);
  double length() const override { return length_; }
  CurvePoint at(double s) const override;
  Vec3 start() const override { return a_; }
  Vec3 end() const override { return b_; }
  double max_curvature() const override { return 0.0; }

 private:
  Vec3 a_;
  Vec3 b_;
  Vec3 direction_;
  double length_;
};

}  // namespace drycut::geometry
