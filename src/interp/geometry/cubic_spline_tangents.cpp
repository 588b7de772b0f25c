#include "interp/geometry/cubic_spline_tangents.hpp"

#include "interp/geometry/parabola_tangent.hpp"

namespace drycut::geometry {

std::vector<Vec3> cubic_spline_tangents(std::span<const Vec3> points, std::span<const double> steps,
                                        const TangentCondition& begin, const TangentCondition& end) {
  CubicSplineScratch scratch;
  const auto m = cubic_spline_tangents(points, steps, begin, end, scratch);
  return {m.begin(), m.end()};
}

std::span<const Vec3> cubic_spline_tangents(std::span<const Vec3> points, std::span<const double> steps,
                                            const TangentCondition& begin, const TangentCondition& end,
                                            CubicSplineScratch& scratch) {
  using Kind = TangentCondition::Kind;
  const size_t n = points.size() - 1;  // number of intervals
  const auto& h = steps;
  auto& d = scratch.slopes;
  d.resize(n);
  for (size_t i = 0; i < n; ++i) d[i] = (points[i + 1] - points[i]) / h[i];

  Kind kb = begin.kind, ke = end.kind;
  if (n < 2) {
    if (kb == Kind::NotAKnot) kb = Kind::Natural;
    if (ke == Kind::NotAKnot) ke = Kind::Natural;
  } else if (n == 2 && kb == Kind::NotAKnot && ke == Kind::NotAKnot) {
    // Both conditions say "one cubic over both intervals": only the parabola is determined.
    const Vec3 m0 = parabola_start_tangent(points[0], points[1], points[2], h[0], h[1]);
    const Vec3 m2 = parabola_end_tangent(points[0], points[1], points[2], h[0], h[1]);
    scratch.tangents.assign({m0, 2.0 * d[0] - m0, m2});
    return scratch.tangents;
  }

  // Tridiagonal rows: lower[i] m_{i-1} + diag[i] m_i + upper[i] m_{i+1} = rhs[i].
  auto &lower = scratch.lower, &diag = scratch.diag, &upper = scratch.upper;
  auto& rhs = scratch.rhs;
  lower.assign(n + 1, 0.0);
  diag.assign(n + 1, 0.0);
  upper.assign(n + 1, 0.0);
  rhs.assign(n + 1, Vec3::Zero());
  switch (kb) {
    case Kind::Clamped: diag[0] = 1.0; rhs[0] = begin.tangent; break;
    case Kind::Natural: diag[0] = 2.0; upper[0] = 1.0; rhs[0] = 3.0 * d[0]; break;
    case Kind::NotAKnot:  // third derivative continuous at point 1, m_2 eliminated
      diag[0] = h[1];
      upper[0] = h[0] + h[1];
      rhs[0] = (d[0] * h[1] * (2.0 * h[1] + 3.0 * h[0]) + d[1] * h[0] * h[0]) / (h[0] + h[1]);
      break;
  }
  for (size_t i = 1; i < n; ++i) {
    lower[i] = h[i];
    diag[i] = 2.0 * (h[i - 1] + h[i]);
    upper[i] = h[i - 1];
    rhs[i] = 3.0 * (h[i] * d[i - 1] + h[i - 1] * d[i]);
  }
  switch (ke) {
    case Kind::Clamped: diag[n] = 1.0; rhs[n] = end.tangent; break;
    case Kind::Natural: lower[n] = 1.0; diag[n] = 2.0; rhs[n] = 3.0 * d[n - 1]; break;
    case Kind::NotAKnot: {
      const double a = h[n - 2], b = h[n - 1];
      lower[n] = a + b;
      diag[n] = a;
      rhs[n] = (d[n - 1] * a * (2.0 * a + 3.0 * b) + d[n - 2] * b * b) / (a + b);
      break;
    }
  }
  // Thomas algorithm (forward elimination, back substitution).
  for (size_t i = 1; i <= n; ++i) {
    const double f = lower[i] / diag[i - 1];
    diag[i] -= f * upper[i - 1];
    rhs[i] -= f * rhs[i - 1];
  }
  auto& m = scratch.tangents;
  m.resize(n + 1);
  m[n] = rhs[n] / diag[n];
  for (size_t i = n; i-- > 0;) m[i] = (rhs[i] - upper[i] * m[i + 1]) / diag[i];
  return m;
}

}  // namespace drycut::geometry
