// ASPLINE: Akima spline with chord-length parameter (see spline_builder.hpp for the rules).
#include <array>
#include <cmath>

#include "interp/geometry/cubic_spline_tangents.hpp"
#include "interp/geometry/hermite_spline_builder.hpp"
#include "interp/geometry/parabola_tangent.hpp"

namespace drycut::geometry {
namespace {

TangentCondition as_tangent_condition(const SplineEnd& e) {
  if (e.condition == EndCondition::Tangent && e.tangent.norm() > 0.0) {
    return {TangentCondition::Kind::Clamped, e.tangent.normalized()};
  }
  return {TangentCondition::Kind::Natural, Vec3::Zero()};  // Auto needs 3 points: not here
}

class AkimaBuilder final : public HermiteSplineBuilder {
 public:
  explicit AkimaBuilder(const SplineEnd& begin) : HermiteSplineBuilder(true), begin_(begin) {}

 private:
  // Chord slope of interval k (node k -> k+1); one slope beyond either end is extrapolated.
  Vec3 slope(long k, size_t last) const {
    const long n = static_cast<long>(last);
    if (k < 0) return 2.0 * slope(0, last) - slope(1, last);
    if (k >= n) return 2.0 * slope(n - 1, last) - slope(n - 2, last);
    const Node& b = node(static_cast<size_t>(k) + 1);
    return (b.point - node(static_cast<size_t>(k)).point) / b.step;
  }

  // The chord slopes m_{i-2}..m_{i+1} around interior node i. Consecutive nodes share three of
  // them, so each slope is computed once (three divisions and two deque lookups per slope); a
  // slope inside the run does not depend on `last`, and one beyond its end is only asked once
  // finished, when `last` no longer changes: the same values as computing all four.
  const std::array<Vec3, 4>& slopes_around(long k, size_t last) {
    if (slopes_at_ == k - 1) {
      slopes_[0] = slopes_[1];
      slopes_[1] = slopes_[2];
      slopes_[2] = slopes_[3];
      slopes_[3] = slope(k + 1, last);
    } else {
      for (long j = 0; j < 4; ++j) slopes_[static_cast<size_t>(j)] = slope(k - 2 + j, last);
    }
    slopes_at_ = k;
    return slopes_;
  }

  // Classical Akima rule per axis at interior node i.
  Vec3 akima_tangent(size_t i, size_t last) {
    const auto& m = slopes_around(static_cast<long>(i), last);  // i >= 1: at most m_{-1} lies beyond the run
    const Vec3 &m_2 = m[0], &m_1 = m[1], &m0 = m[2], &m1 = m[3];
    Vec3 t;
    for (int a = 0; a < 3; ++a) {
      const double w_left = std::abs(m1[a] - m0[a]);   // weights the slope before the point
      const double w_right = std::abs(m_1[a] - m_2[a]);
      const double sum = w_left + w_right;
      t[a] = sum > 1e-12 ? (w_left * m_1[a] + w_right * m0[a]) / sum : 0.5 * (m_1[a] + m0[a]);
    }
    return t;
  }

  Vec3 end_tangent(const SplineEnd& e, bool at_start) const {
    const size_t last = count() - 1;
    if (e.condition == EndCondition::Tangent && e.tangent.norm() > 0.0) return e.tangent.normalized();
    if (e.condition == EndCondition::Auto && last >= 2) {
      return at_start ? parabola_start_tangent(node(0).point, node(1).point, node(2).point, node(1).step, node(2).step)
                      : parabola_end_tangent(node(last - 2).point, node(last - 1).point, node(last).point,
                                             node(last - 1).step, node(last).step);
    }
    // Natural: zero second derivative at the end of the Hermite cubic next to it.
    if (at_start) return 0.5 * (3.0 * slope(0, last) - node(1).tangent);
    return 0.5 * (3.0 * slope(static_cast<long>(last) - 1, last) - node(last - 1).tangent);
  }

  void update_tangents() override {
    const size_t n = count();
    if (n < 2) return;
    const size_t last = n - 1;
    if (finished() && last == 1) {
      // Two points: the cubic fixed by the two end conditions alone.
      const Vec3 pts[2] = {node(0).point, node(1).point};
      const double steps[1] = {node(1).step};
      const auto m = cubic_spline_tangents(pts, steps, as_tangent_condition(begin_),
                                           as_tangent_condition(end_condition()));
      for (size_t i = 0; i < 2; ++i) { node(i).tangent = m[i]; node(i).has_tangent = true; }
      start_done_ = true;
      return;
    }
    while (next_interior_ + 1 <= last && (finished() || next_interior_ + 2 <= last)) {
      node(next_interior_).tangent = akima_tangent(next_interior_, last);
      node(next_interior_).has_tangent = true;
      ++next_interior_;
    }
    if (!start_done_ && node(1).has_tangent) {
      node(0).tangent = end_tangent(begin_, true);
      node(0).has_tangent = true;
      start_done_ = true;
    }
    if (finished() && !node(last).has_tangent) {
      node(last).tangent = end_tangent(end_condition(), false);
      node(last).has_tangent = true;
    }
  }

  size_t needed_from() const override {
    if (!start_done_) return 0;
    return next_interior_ >= 2 ? next_interior_ - 2 : 0;
  }

  SplineEnd begin_;
  std::array<Vec3, 4> slopes_;
  long slopes_at_ = -10;  // node whose slopes slopes_ holds (none yet)
  size_t next_interior_ = 1;
  bool start_done_ = false;
};

}  // namespace

std::unique_ptr<SplineBuilder> make_akima_builder(const SplineEnd& begin) {
  return std::make_unique<AkimaBuilder>(begin);
}

}  // namespace drycut::geometry
