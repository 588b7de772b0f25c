// CSPLINE: cubic spline with chord-length parameter, global or windowed (MD20160), see
// spline_builder.hpp for the rules.
#include <algorithm>
#include <vector>

#include "interp/geometry/cubic_spline_tangents.hpp"
#include "interp/geometry/hermite_spline_builder.hpp"
#include "interp/geometry/parabola_tangent.hpp"

namespace drycut::geometry {
namespace {

TangentCondition as_tangent_condition(const SplineEnd& e) {
  switch (e.condition) {
    case EndCondition::Tangent:
      if (e.tangent.norm() > 0.0) return {TangentCondition::Kind::Clamped, e.tangent.normalized()};
      return {};
    case EndCondition::Auto: return {TangentCondition::Kind::NotAKnot, Vec3::Zero()};
    case EndCondition::Natural: break;
  }
  return {};
}

class CubicBuilder final : public HermiteSplineBuilder {
 public:
  CubicBuilder(const SplineEnd& begin, int window_blocks)
      : HermiteSplineBuilder(false),
        begin_(as_tangent_condition(begin)),
        // Fewer than two points either side would leave no room for the cut-off parabola.
        half_(window_blocks <= 0 ? 0 : std::max<size_t>(2, static_cast<size_t>(window_blocks) / 2)) {}

 private:
  // Solves the spline over nodes lo..hi and returns the tangent at node j.
  Vec3 window_tangent(size_t j, size_t lo, size_t hi, const TangentCondition& left,
                      const TangentCondition& right) {
    copy_window(lo, hi, points_, steps_);
    return cubic_spline_tangent_at(points_, steps_, left, right, j - lo);
  }

  void update_tangents() override {
    const size_t n = count();
    if (n < 2) return;
    const size_t last = n - 1;
    if (half_ == 0) {
      if (!finished()) return;
      copy_window(0, last, points_, steps_);
      const auto m = cubic_spline_tangents(points_, steps_, begin_, as_tangent_condition(end_condition()), scratch_);
      for (size_t i = 0; i <= last; ++i) { node(i).tangent = m[i]; node(i).has_tangent = true; }
      next_tangent_ = n;
      return;
    }
    // The run's first and last tangents are derived from their neighbours so that the end
    // condition holds exactly for the end span (each interior tangent comes from its own window).
    if (next_tangent_ == 0) next_tangent_ = 1;
    // A window is only cut on the right once a point beyond it exists; otherwise the run might
    // end there and the end condition would apply.
    while (next_tangent_ < last && (finished() || next_tangent_ + half_ + 1 <= last)) {
      const size_t j = next_tangent_;
      const size_t lo = j >= half_ ? j - half_ : 0;
      const size_t hi = std::min(last, j + half_);
      TangentCondition left = begin_, right = as_tangent_condition(end_condition());
      if (lo > 0) {
        left = {TangentCondition::Kind::Clamped,
                parabola_start_tangent(node(lo).point, node(lo + 1).point, node(lo + 2).point,
                                       node(lo + 1).step, node(lo + 2).step)};
      }
      if (!finished() || hi < last) {
        right = {TangentCondition::Kind::Clamped,
                 parabola_end_tangent(node(hi - 2).point, node(hi - 1).point, node(hi).point,
                                      node(hi - 1).step, node(hi).step)};
      }
      node(j).tangent = window_tangent(j, lo, hi, left, right);
      node(j).has_tangent = true;
      ++next_tangent_;
    }
    if (!start_done_ && (last >= 3 || finished()) && (last == 1 || node(1).has_tangent) &&
        (begin_.kind != TangentCondition::Kind::NotAKnot || last < 3 || node(2).has_tangent)) {
      set_end_tangent(true, begin_);
      start_done_ = true;
    }
    if (finished() && start_done_ && !node(last).has_tangent) set_end_tangent(false, as_tangent_condition(end_condition()));
  }

  // Tangent at the first (at_start) or last node from its end condition and the neighbouring
  // tangents (Hermite end span: P''=0 for Natural; P''' continuous at the next node for
  // not-a-knot). Short runs are solved whole.
  void set_end_tangent(bool at_start, const TangentCondition& cond) {
    const size_t last = count() - 1;
    if (last <= 2) {
      // The whole run fits one solve: both ends at once.
      copy_window(0, last, points_, steps_);
      const auto m = cubic_spline_tangents(points_, steps_, begin_, as_tangent_condition(end_condition()), scratch_);
      for (size_t i = 0; i <= last; ++i) { node(i).tangent = m[i]; node(i).has_tangent = true; }
      return;
    }
    const size_t e = at_start ? 0 : last;       // the end node
    const size_t n1 = at_start ? 1 : last - 1;  // its neighbour
    const size_t n2 = at_start ? 2 : last - 2;
    const double sign = at_start ? 1.0 : -1.0;  // walking inwards reverses the parameter at the end
    const double h0 = at_start ? node(1).step : node(last).step;
    const double h1 = at_start ? node(2).step : node(last - 1).step;
    // Chord slopes walking inwards are already in the (possibly reversed) inward parameter.
    const Vec3 d0 = (node(n1).point - node(e).point) / h0;
    const Vec3 d1 = (node(n2).point - node(n1).point) / h1;
    const Vec3 m1 = sign * node(n1).tangent;
    Vec3 m = Vec3::Zero();
    switch (cond.kind) {
      case TangentCondition::Kind::Clamped: m = sign * cond.tangent; break;
      case TangentCondition::Kind::Natural: m = 0.5 * (3.0 * d0 - m1); break;
      case TangentCondition::Kind::NotAKnot: {
        const Vec3 m2 = sign * node(n2).tangent;
        m = 2.0 * d0 - m1 + (h0 * h0) / (h1 * h1) * (m1 + m2 - 2.0 * d1);
        break;
      }
    }
    node(e).tangent = sign * m;
    node(e).has_tangent = true;
  }

  size_t needed_from() const override {
    if (half_ == 0 || !start_done_) return 0;
    return next_tangent_ >= half_ ? next_tangent_ - half_ : 0;
  }

  TangentCondition begin_;
  size_t half_;
  size_t next_tangent_ = 0;
  bool start_done_ = false;
  std::vector<Vec3> points_;   // scratch for one window
  std::vector<double> steps_;
  CubicSplineScratch scratch_;  // one solve per point: no allocation per solve
};

}  // namespace

std::unique_ptr<SplineBuilder> make_cubic_builder(const SplineEnd& begin, int window_blocks) {
  return std::make_unique<CubicBuilder>(begin, window_blocks);
}

}  // namespace drycut::geometry
