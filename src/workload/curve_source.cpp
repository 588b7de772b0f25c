#include "workload/curve_source.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace drycut::workload {

CurveSource polar_curve(std::function<double(double)> radius) {
  CurveSource c;
  c.point = [radius = std::move(radius)](double t) {
    const double r = radius(t);
    return Vec3(r * std::cos(t), r * std::sin(t), 0.0);
  };
  c.t_begin = 0.0;
  c.t_end = 2.0 * std::numbers::pi;
  return c;
}

double thesis_radius(double theta) { return 18.0 + 4.0 * std::cos(6.0 * theta) * std::cos(2.0 * theta); }

namespace {
// 5-point Gauss-Legendre nodes and weights on [-1, 1].
constexpr std::array<double, 5> kNodes{0.0, -0.5384693101056831, 0.5384693101056831, -0.9061798459386640,
                                       0.9061798459386640};
constexpr std::array<double, 5> kWeights{0.5688888888888889, 0.4786286704993665, 0.4786286704993665,
                                         0.2369268850561891, 0.2369268850561891};
}  // namespace

ArcLengthTable::ArcLengthTable(const CurveSource& curve, double t_begin, double t_end, int intervals)
    : curve_(curve), t0_(t_begin), dt_((t_end - t_begin) / intervals) {
  s_.resize(static_cast<size_t>(intervals) + 1, 0.0);
  for (int i = 0; i < intervals; ++i) {
    const double mid = t0_ + (i + 0.5) * dt_;
    double sum = 0.0;
    for (size_t k = 0; k < kNodes.size(); ++k) sum += kWeights[k] * speed(mid + 0.5 * dt_ * kNodes[k]);
    s_[static_cast<size_t>(i) + 1] = s_[static_cast<size_t>(i)] + 0.5 * dt_ * sum;
  }
}

double ArcLengthTable::speed(double t) const {
  const double h = 1e-6 * std::max(1.0, std::abs(t));
  return (curve_.point(t + h) - curve_.point(t - h)).norm() / (2.0 * h);
}

double ArcLengthTable::length_at(double t) const {
  const double x = std::clamp((t - t0_) / dt_, 0.0, static_cast<double>(s_.size() - 1));
  const size_t i = std::min(static_cast<size_t>(x), s_.size() - 2);
  // Integrate the partial interval exactly rather than interpolating linearly.
  const double a = t0_ + static_cast<double>(i) * dt_;
  const double b = t0_ + x * dt_;
  double sum = 0.0;
  for (size_t k = 0; k < kNodes.size(); ++k) sum += kWeights[k] * speed(0.5 * (a + b) + 0.5 * (b - a) * kNodes[k]);
  return s_[i] + 0.5 * (b - a) * sum;
}

double ArcLengthTable::parameter_at(double s) const {
  s = std::clamp(s, 0.0, total());
  const auto it = std::upper_bound(s_.begin(), s_.end(), s);
  const size_t i = std::min<size_t>(static_cast<size_t>(std::max<std::ptrdiff_t>(it - s_.begin() - 1, 0)), s_.size() - 2);
  // Newton on the exact partial integral, started by linear interpolation inside the interval.
  double lo = t0_ + static_cast<double>(i) * dt_, hi = lo + dt_;
  double t = lo + dt_ * (s - s_[i]) / std::max(1e-300, s_[i + 1] - s_[i]);
  for (int iter = 0; iter < 30; ++iter) {
    const double f = length_at(t) - s;
    if (std::abs(f) < 1e-12) break;
    if (f > 0) hi = t; else lo = t;
    const double v = speed(t);
    double next = v > 0 ? t - f / v : 0.5 * (lo + hi);
    if (next <= lo || next >= hi) next = 0.5 * (lo + hi);
    t = next;
  }
  return t;
}

}  // namespace drycut::workload
