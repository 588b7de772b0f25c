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

namespace {
// Row i of the system: lower m_{i-1} + diag m_i + upper m_{i+1} = rhs (n >= 2 intervals, the
// end conditions as in the full solve).
struct TangentRow {
  double lower = 0.0, diag = 0.0, upper = 0.0;
  Vec3 rhs = Vec3::Zero();
};

TangentRow tangent_row(std::span<const Vec3> p, std::span<const double> h, const TangentCondition& begin,
                       const TangentCondition& end, size_t i) {
  using Kind = TangentCondition::Kind;
  const size_t n = h.size();
  const auto d = [&](size_t k) -> Vec3 { return (p[k + 1] - p[k]) / h[k]; };
  TangentRow r;
  if (i == 0) {
    switch (begin.kind) {
      case Kind::Clamped: r.diag = 1.0; r.rhs = begin.tangent; break;
      case Kind::Natural: r.diag = 2.0; r.upper = 1.0; r.rhs = 3.0 * d(0); break;
      case Kind::NotAKnot:
        r.diag = h[1];
        r.upper = h[0] + h[1];
        r.rhs = (d(0) * h[1] * (2.0 * h[1] + 3.0 * h[0]) + d(1) * h[0] * h[0]) / (h[0] + h[1]);
        break;
    }
  } else if (i == n) {
    switch (end.kind) {
      case Kind::Clamped: r.diag = 1.0; r.rhs = end.tangent; break;
      case Kind::Natural: r.lower = 1.0; r.diag = 2.0; r.rhs = 3.0 * d(n - 1); break;
      case Kind::NotAKnot: {
        const double a = h[n - 2], b = h[n - 1];
        r.lower = a + b;
        r.diag = a;
        r.rhs = (d(n - 1) * a * (2.0 * a + 3.0 * b) + d(n - 2) * b * b) / (a + b);
        break;
      }
    }
  } else {
    r.lower = h[i];
    r.diag = 2.0 * (h[i - 1] + h[i]);
    r.upper = h[i - 1];
    r.rhs = 3.0 * (h[i] * d(i - 1) + h[i - 1] * d(i));
  }
  return r;
}
}  // namespace

Vec3 cubic_spline_tangent_at(std::span<const Vec3> points, std::span<const double> steps,
                             const TangentCondition& begin, const TangentCondition& end, size_t j) {
  using Kind = TangentCondition::Kind;
  const size_t n = steps.size();
  const bool not_a_knot_either = begin.kind == Kind::NotAKnot || end.kind == Kind::NotAKnot;
  // The end conditions' special cases (too few points for not-a-knot) are the full solve's.
  if (n < 2 || (n == 2 && not_a_knot_either)) return cubic_spline_tangents(points, steps, begin, end)[j];
  const auto& h = steps;
  const auto slope = [&](size_t k) -> Vec3 { return (points[k + 1] - points[k]) / h[k]; };
  // An interior row i: h_i m_{i-1} + 2 (h_{i-1} + h_i) m_i + h_{i-1} m_{i+1} = 3 (h_i d_{i-1} + h_{i-1} d_i).
  const auto interior = [&](size_t i, const Vec3& d_before, const Vec3& d_after) {
    return TangentRow{h[i], 2.0 * (h[i - 1] + h[i]), h[i - 1], 3.0 * (h[i] * d_before + h[i - 1] * d_after)};
  };
  // Downwards: row i-1 reduced to D m_{i-1} + U m_i = R (slopes carried from row to row).
  double D = 0.0, U = 0.0;
  Vec3 R = Vec3::Zero();
  Vec3 d_prev = slope(0);
  for (size_t i = 0; i < j; ++i) {
    if (i == 0) {
      const TangentRow r = tangent_row(points, steps, begin, end, 0);
      D = r.diag;
      R = r.rhs;
      U = r.upper;
      continue;
    }
    const Vec3 d_next = slope(i);
    const TangentRow r = interior(i, d_prev, d_next);
    d_prev = d_next;
    const double f = r.lower / D;
    D = r.diag - f * U;
    R = r.rhs - f * R;
    U = r.upper;
  }
  // Upwards: row i+1 reduced to L m_i + E m_{i+1} = S.
  double E = 0.0, L = 0.0;
  Vec3 S = Vec3::Zero();
  Vec3 d_after = slope(n - 1);
  for (size_t i = n; i > j; --i) {
    if (i == n) {
      const TangentRow r = tangent_row(points, steps, begin, end, n);
      E = r.diag;
      S = r.rhs;
      L = r.lower;
      continue;
    }
    const Vec3 d_before = slope(i - 1);
    const TangentRow r = interior(i, d_before, d_after);
    d_after = d_before;
    const double g = r.upper / E;
    E = r.diag - g * L;
    S = r.rhs - g * S;
    L = r.lower;
  }
  const TangentRow r = (j == 0 || j == n) ? tangent_row(points, steps, begin, end, j)
                                          : interior(j, slope(j - 1), slope(j));
  double diag = r.diag;
  Vec3 rhs = r.rhs;
  if (j > 0) {
    diag -= r.lower * U / D;
    rhs -= (r.lower / D) * R;
  }
  if (j < n) {
    diag -= r.upper * L / E;
    rhs -= (r.upper / E) * S;
  }
  return rhs / diag;
}

}  // namespace drycut::geometry
