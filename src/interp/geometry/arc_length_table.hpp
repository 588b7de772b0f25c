#pragma once
// Arc length of a parametric curve and its inverse s -> u, from the speed |dP/du| alone.
//
// Length: adaptive Gauss-Legendre quadrature (5 nodes). An interval is accepted when its
// 5-node value and the sum over its two halves agree to 1e-11 of the first estimate of the total
// length, so the relative length error is far below the required 1e-6. The accepted interval
// ends form a small table (u_k, s_k), typically 3-9 entries for a spline span (two first intervals).
// Inverse: the table brackets s; Newton on s(u) - s = 0 inside the bracket, with s(u) from the
// same 5-node rule over [u_k, u], falls back to bisection when a step leaves the bracket.
#include <functional>
#include <vector>

namespace drycut::geometry {

class ArcLengthTable {
 public:
  using Speed = std::function<double(double)>;

  ArcLengthTable() = default;
  ArcLengthTable(const Speed& speed, double u_begin, double u_end);

  double length() const { return s_.empty() ? 0.0 : s_.back(); }
  // Parameter at arc length s (clamped to [0, length()]).
  double parameter_at(const Speed& speed, double s) const;
  size_t size() const { return u_.size(); }

  // 5-node Gauss-Legendre integral of speed over [a, b].
  static double gauss5(const Speed& speed, double a, double b);

 private:
  std::vector<double> u_;
  std::vector<double> s_;
};

}  // namespace drycut::geometry
