#pragma once
// Analytic test curves for the radius compensation tests (closed forms, independent of the code
// under test).
#include <algorithm>
#include <cmath>

#include "interp/geometry/curve.hpp"

namespace drycut::test {

// The parabola y = a x^2 (z = z0) for x in [x0, x1], travelled towards +x and evaluated by arc
// length. Radius of curvature at the vertex: 1 / (2a); the curve turns left (counter-clockwise
// seen from +Z) when a > 0, so its left side is the concave one.
class ParabolaCurve final : public geometry::Curve {
 public:
  ParabolaCurve(double a, double x0, double x1, double z0 = 0.0) : a_(a), x0_(x0), x1_(x1), z0_(z0) {
    length_ = primitive(x1_) - primitive(x0_);
  }
  double length() const override { return length_; }
  double max_curvature() const override {
    const double x = (x0_ <= 0.0 && x1_ >= 0.0) ? 0.0 : std::min(std::abs(x0_), std::abs(x1_));
    return curvature_at_x(x);
  }
  geometry::CurvePoint at(double s) const override {
    s = std::clamp(s, 0.0, length_);
    const double x = x_at(s);
    const double g = std::sqrt(1.0 + 4.0 * a_ * a_ * x * x);
    geometry::CurvePoint p;
    p.position = {x, a_ * x * x, z0_};
    p.tangent = geometry::Vec3(1.0, 2.0 * a_ * x, 0.0) / g;
    p.curvature_vector = geometry::Vec3(-4.0 * a_ * a_ * x, 2.0 * a_, 0.0) / std::pow(g, 4);
    const geometry::Vec3 dk_dx = geometry::Vec3(-4.0 * a_ * a_, 0.0, 0.0) / std::pow(g, 4) +
                                 geometry::Vec3(-4.0 * a_ * a_ * x, 2.0 * a_, 0.0) * (-16.0 * a_ * a_ * x / std::pow(g, 6));
    p.curvature_rate = dk_dx / g;
    p.curvature = curvature_at_x(x);
    p.curvature_derivative = -24.0 * a_ * a_ * a_ * x / std::pow(g, 6);  // d(2a g^-3)/dx / g
    return p;
  }
  double x_at(double s) const {
    double x = x0_ + (x1_ - x0_) * s / length_;
    for (int i = 0; i < 100; ++i) {
      const double f = primitive(x) - primitive(x0_) - s;
      x -= f / std::sqrt(1.0 + 4.0 * a_ * a_ * x * x);
      if (std::abs(f) < 1e-14) break;
    }
    return x;
  }
  // Arc length from x = 0 to x (signed).
  double primitive(double x) const {
    const double g = std::sqrt(1.0 + 4.0 * a_ * a_ * x * x);
    return 0.5 * x * g + std::asinh(2.0 * a_ * x) / (4.0 * a_);
  }
  double curvature_at_x(double x) const { return 2.0 * a_ / std::pow(1.0 + 4.0 * a_ * a_ * x * x, 1.5); }
  // Tangent angle against +x.
  double angle_at_x(double x) const { return std::atan(2.0 * a_ * x); }

 private:
  double a_, x0_, x1_, z0_;
  double length_;
};

}  // namespace drycut::test
