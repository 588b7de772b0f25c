#pragma once
// Analytic test curves for the radius compensation tests (closed forms, independent of the code
// under test).
#include <algorithm>
#include <cmath>
#include <utility>

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

// A curve in the plane z = const climbed at a constant grade g (mm of Z per mm in the plane):
//   P(S) = B(s) + g s e_z,   s = S / sqrt(1 + g^2)
// so dP/dS = (T_B + g e_z) / w, d2P/dS2 = K_B / w^2, d3P/dS3 = K'_B / w^3 with w = sqrt(1 + g^2).
class GradedCurve final : public geometry::Curve {
 public:
  GradedCurve(geometry::CurvePtr flat, double grade)
      : flat_(std::move(flat)), grade_(grade), w_(std::sqrt(1.0 + grade * grade)) {}
  double length() const override { return flat_->length() * w_; }
  double max_curvature() const override { return flat_->max_curvature() / (w_ * w_); }
  geometry::CurvePoint at(double S) const override {
    const double s = std::clamp(S / w_, 0.0, flat_->length());
    const geometry::CurvePoint b = flat_->at(s);
    geometry::CurvePoint p;
    p.position = b.position + geometry::Vec3(0, 0, grade_ * s);
    p.tangent = (b.tangent + geometry::Vec3(0, 0, grade_)) / w_;
    p.curvature_vector = b.curvature_vector / (w_ * w_);
    p.curvature_rate = b.curvature_rate / (w_ * w_ * w_);
    p.curvature = p.curvature_vector.norm();
    p.curvature_derivative = b.curvature_derivative / (w_ * w_ * w_);
    return p;
  }

 private:
  geometry::CurvePtr flat_;
  double grade_, w_;
};

}  // namespace drycut::test
