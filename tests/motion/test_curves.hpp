#pragma once
// Minimal curves for planner tests, written independently of src/interp/geometry.
#include <cmath>
#include <memory>

#include "interp/geometry/curve.hpp"

namespace drycut::motion::testing {

using geometry::CurvePoint;
using geometry::Vec3;

class TestLine : public geometry::Curve {
 public:
  TestLine(Vec3 a, Vec3 b) : a_(a), b_(b), length_((b - a).norm()) {}
  double length() const override { return length_; }
  CurvePoint at(double s) const override {
    CurvePoint p;
    s = std::clamp(s, 0.0, length_);
    p.tangent = length_ > 0 ? Vec3((b_ - a_) / length_) : Vec3::UnitX();
    p.position = a_ + p.tangent * s;
    return p;
  }
  double max_curvature() const override { return 0; }

 private:
  Vec3 a_, b_;
  double length_;
};

// Circle arc in the XY plane: centre, radius, start angle, signed sweep (rad, + = CCW).
class TestArc : public geometry::Curve {
 public:
  TestArc(Vec3 centre, double radius, double start_angle, double sweep)
      : c_(centre), r_(radius), a0_(start_angle), sweep_(sweep) {}
  double length() const override { return r_ * std::abs(sweep_); }
  CurvePoint at(double s) const override {
    s = std::clamp(s, 0.0, length());
    const double dir = sweep_ >= 0 ? 1.0 : -1.0;
    const double phi = a0_ + dir * s / r_;
    const Vec3 radial(std::cos(phi), std::sin(phi), 0.0);
    const Vec3 tangent = dir * Vec3(-std::sin(phi), std::cos(phi), 0.0);
    CurvePoint p;
    p.position = c_ + r_ * radial;
    p.tangent = tangent;
    p.curvature_vector = -radial / r_;           // points to the centre, |.| = 1/r
    p.curvature_rate = -tangent / (r_ * r_);     // d/ds of the curvature vector
    p.curvature = 1.0 / r_;
    p.curvature_derivative = 0.0;
    return p;
  }
  double max_curvature() const override { return 1.0 / r_; }

 private:
  Vec3 c_;
  double r_, a0_, sweep_;
};

}  // namespace drycut::motion::testing
