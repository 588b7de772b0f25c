#include "interp/geometry/arc_length_table.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace drycut::geometry {
namespace {

// Gauss-Legendre 5-point nodes and weights on [-1, 1].
constexpr std::array<double, 5> kNodes{-0.9061798459386640, -0.5384693101056831, 0.0,
                                       0.5384693101056831, 0.9061798459386640};
constexpr std::array<double, 5> kWeights{0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                                         0.4786286704993665, 0.2369268850561891};
// Two, not more: a spline span's speed is smooth, so most spans are accepted at the first
// halving (6 five-node integrals, the span's main construction cost).
constexpr int kInitialIntervals = 2;
constexpr int kMaxDepth = 30;
// A span whose speed has a cusp (repeated control points, weights) never meets the tolerance
// near it; without a bound on the intervals the depth limit alone allows 2^30 of them (a hang
// found by the fuzzer). Past this many the rest is accepted as it is: the cusp's length is
// still integrated by Gauss, only less finely.
constexpr size_t kMaxIntervals = size_t{1} << 16;

}  // namespace

double ArcLengthTable::gauss5(const Speed& speed, double a, double b) {
  const double half = 0.5 * (b - a), mid = 0.5 * (a + b);
  double sum = 0.0;
  for (size_t i = 0; i < kNodes.size(); ++i) sum += kWeights[i] * speed(mid + half * kNodes[i]);
  return sum * half;
}

ArcLengthTable::ArcLengthTable(const Speed& speed, double u_begin, double u_end) {
  u_.push_back(u_begin);
  s_.push_back(0.0);
  if (!(u_end > u_begin)) return;
  // The first intervals' values are the first estimate of the length and the stack's start.
  const double step = (u_end - u_begin) / kInitialIntervals;
  struct Interval { double a, b, whole; int depth; };
  std::array<Interval, kInitialIntervals> initial{};
  double estimate = 0.0;
  for (int i = 0; i < kInitialIntervals; ++i) {
    const double a = u_begin + i * step;
    const double b = i + 1 == kInitialIntervals ? u_end : a + step;
    initial[static_cast<size_t>(i)] = {a, b, gauss5(speed, a, b), 0};
    estimate += initial[static_cast<size_t>(i)].whole;
  }
  const double tol = 1e-11 * std::max(estimate, 1e-300);

  // Depth-first over intervals, left to right, so accepted ends come out in order.
  std::vector<Interval> stack(initial.rbegin(), initial.rend());
  while (!stack.empty()) {
    const Interval iv = stack.back();
    stack.pop_back();
    const double m = 0.5 * (iv.a + iv.b);
    const double left = gauss5(speed, iv.a, m), right = gauss5(speed, m, iv.b);
    if (std::abs(left + right - iv.whole) <= tol || iv.depth >= kMaxDepth ||
        u_.size() + stack.size() >= kMaxIntervals) {
      u_.push_back(iv.b);
      s_.push_back(s_.back() + left + right);
    } else {
      stack.push_back({m, iv.b, right, iv.depth + 1});
      stack.push_back({iv.a, m, left, iv.depth + 1});
    }
  }
}

double ArcLengthTable::parameter_at(const Speed& speed, double s) const {
  if (u_.size() < 2 || s <= 0.0) return u_.empty() ? 0.0 : u_.front();
  if (s >= s_.back()) return u_.back();
  const size_t k = static_cast<size_t>(std::upper_bound(s_.begin(), s_.end(), s) - s_.begin()) - 1;
  double lo = u_[k], hi = u_[k + 1];
  const double s0 = s_[k], ds = s_[k + 1] - s_[k];
  double u = ds > 0.0 ? lo + (hi - lo) * (s - s0) / ds : lo;
  const double tol = 1e-13 * std::max(1.0, s_.back());
  for (int it = 0; it < 60; ++it) {
    const double f = s0 + gauss5(speed, u_[k], u) - s;
    if (std::abs(f) <= tol) break;
    if (f > 0.0) hi = u; else lo = u;
    const double v = speed(u);
    double next = v > 0.0 ? u - f / v : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (hi - lo < 1e-15 * std::max(1.0, std::abs(u))) break;
    u = next;
  }
  return u;
}

}  // namespace drycut::geometry
