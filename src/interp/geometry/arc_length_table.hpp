#pragma once
// Arc length of a parametric curve and its inverse s -> u, from the speed |dP/du| alone.
//
// Length: adaptive Gauss-Legendre quadrature (5 nodes). An interval is accepted when its
// 5-node value and the sum over its two halves agree to 1e-11 of the first estimate of the total
// length, so the relative length error is far below the required 1e-6. The accepted interval
// ends form a small table (u_k, s_k), typically 3-9 entries for a spline span (two first intervals).
// Inverse: the table brackets s; Newton on s(u) - s = 0 inside the bracket, with s(u) from the
// same 5-node rule over [u_k, u], falls back to bisection when a step leaves the bracket.
//
// Cost (one table per spline block, the spline programs' hot path): the speed is a template
// parameter (inlined, no std::function call per node; a polynomial span's evaluates the five
// nodes two per SIMD vector), the first kInline entries live inside the table and the interval
// stack on the stack, so a typical span's table allocates nothing.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace drycut::geometry {

namespace arc_length_detail {
// Gauss-Legendre 5-point nodes and weights on [-1, 1].
inline constexpr std::array<double, 5> kNodes{-0.9061798459386640, -0.5384693101056831, 0.0,
                                              0.5384693101056831, 0.9061798459386640};
inline constexpr std::array<double, 5> kWeights{0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                                                0.4786286704993665, 0.2369268850561891};
// Two, not more: a spline span's speed is smooth, so most spans are accepted at the first
// halving (6 five-node integrals, the span's main construction cost).
inline constexpr int kInitialIntervals = 2;
inline constexpr int kMaxDepth = 30;
// A span whose speed has a cusp (repeated control points, weights) never meets the tolerance
// near it; without a bound on the intervals the depth limit alone allows 2^30 of them (a hang
// found by the fuzzer). Past this many the rest is accepted as it is: the cusp's length is
// still integrated by Gauss, only less finely.
inline constexpr size_t kMaxIntervals = size_t{1} << 16;
}  // namespace arc_length_detail

class ArcLengthTable {
 public:
  ArcLengthTable() = default;
  template <typename SpeedFn>
  ArcLengthTable(const SpeedFn& speed, double u_begin, double u_end);

  double length() const { return size_ == 0 ? 0.0 : s(size_ - 1); }
  // Parameter at arc length s (clamped to [0, length()]).
  template <typename SpeedFn>
  double parameter_at(const SpeedFn& speed, double s) const;
  size_t size() const { return size_; }
  // Arc length from the start to parameter u (clamped): the accepted interval's start plus one
  // 5-node integral inside it, as accurate as the table (what parameter_at's Newton steps use).
  template <typename SpeedFn>
  double length_at(const SpeedFn& speed, double u_at) const {
    if (size_ < 2 || u_at <= u(0)) return 0.0;
    if (u_at >= u(size_ - 1)) return length();
    size_t k = 0;  // last k with u(k) <= u_at
    for (size_t n = size_ - 1; n > 1;) {
      const size_t half = n / 2;
      if (u(k + half) <= u_at) k += half;
      n -= half;
    }
    return s(k) + gauss5(speed, u(k), u_at);
  }

  // 5-node Gauss-Legendre integral of speed over [a, b]. A speed that offers
  // `five(u, out)` (the five nodes' speeds at once, the same values as five calls) is asked
  // once; the weighted sum keeps its order either way.
  template <typename SpeedFn>
  static double gauss5(const SpeedFn& speed, double a, double b) {
    using namespace arc_length_detail;
    const double half = 0.5 * (b - a), mid = 0.5 * (a + b);
    double sum = 0.0;
    if constexpr (requires(std::array<double, 5>& x) { speed.five(x, x); }) {
      std::array<double, 5> u, v;
      for (size_t i = 0; i < kNodes.size(); ++i) u[i] = mid + half * kNodes[i];
      speed.five(u, v);
      for (size_t i = 0; i < kNodes.size(); ++i) sum += kWeights[i] * v[i];
    } else {
      for (size_t i = 0; i < kNodes.size(); ++i) sum += kWeights[i] * speed(mid + half * kNodes[i]);
    }
    return sum * half;
  }

 private:
  static constexpr size_t kInline = 9;
  double u(size_t k) const { return k < kInline ? u_in_[k] : u_more_[k - kInline]; }
  double s(size_t k) const { return k < kInline ? s_in_[k] : s_more_[k - kInline]; }
  void push(double u, double s) {
    if (size_ < kInline) {
      u_in_[size_] = u;
      s_in_[size_] = s;
    } else {
      u_more_.push_back(u);
      s_more_.push_back(s);
    }
    ++size_;
  }
  // First k with s(k) > value (as std::upper_bound over s).
  size_t upper(double value) const {
    size_t lo = 0, n = size_;
    while (n > 0) {
      const size_t half = n / 2;
      if (value < s(lo + half)) {
        n = half;
      } else {
        lo += half + 1;
        n -= half + 1;
      }
    }
    return lo;
  }

  std::array<double, kInline> u_in_{};
  std::array<double, kInline> s_in_{};
  std::vector<double> u_more_;
  std::vector<double> s_more_;
  size_t size_ = 0;
};

template <typename SpeedFn>
ArcLengthTable::ArcLengthTable(const SpeedFn& speed, double u_begin, double u_end) {
  using namespace arc_length_detail;
  push(u_begin, 0.0);
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

  // Depth-first over intervals, left to right, so accepted ends come out in order. Each pop
  // pushes at most two, one level deeper: the stack never holds more than
  // kInitialIntervals + kMaxDepth intervals.
  std::array<Interval, kInitialIntervals + kMaxDepth + 2> stack;
  size_t top = 0;
  for (size_t i = kInitialIntervals; i-- > 0;) stack[top++] = initial[i];
  while (top > 0) {
    const Interval iv = stack[--top];
    const double m = 0.5 * (iv.a + iv.b);
    const double left = gauss5(speed, iv.a, m), right = gauss5(speed, m, iv.b);
    if (std::abs(left + right - iv.whole) <= tol || iv.depth >= kMaxDepth || size_ + top >= kMaxIntervals) {
      push(iv.b, s(size_ - 1) + left + right);
    } else {
      stack[top++] = {m, iv.b, right, iv.depth + 1};
      stack[top++] = {iv.a, m, left, iv.depth + 1};
    }
  }
}

template <typename SpeedFn>
double ArcLengthTable::parameter_at(const SpeedFn& speed, double s_target) const {
  if (size_ < 2 || s_target <= 0.0) return size_ == 0 ? 0.0 : u(0);
  if (s_target >= length()) return u(size_ - 1);
  const size_t k = upper(s_target) - 1;
  double lo = u(k), hi = u(k + 1);
  const double s0 = s(k), ds = s(k + 1) - s(k);
  double x = ds > 0.0 ? lo + (hi - lo) * (s_target - s0) / ds : lo;
  const double tol = 1e-13 * std::max(1.0, length());
  for (int it = 0; it < 60; ++it) {
    const double f = s0 + gauss5(speed, u(k), x) - s_target;
    if (std::abs(f) <= tol) break;
    if (f > 0.0) hi = x; else lo = x;
    const double v = speed(x);
    double next = v > 0.0 ? x - f / v : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (hi - lo < 1e-15 * std::max(1.0, std::abs(x))) break;
    x = next;
  }
  return x;
}

}  // namespace drycut::geometry
