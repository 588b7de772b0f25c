#include "interp/geometry/hermite_spline_builder.hpp"

#include <algorithm>
#include <stdexcept>

#include "interp/geometry/polynomial_span.hpp"
#include "interp/geometry/spline_input_check.hpp"
#include "interp/geometry/spline_parametrisation.hpp"

namespace drycut::geometry {

void HermiteSplineBuilder::add_point(const Vec3& p, double /*weight*/, double /*knot_span*/) {
  if (finished_) throw std::logic_error("SplineBuilder::add_point after finish");
  check_spline_point(p);
  const size_t block = next_block_++;
  if (count() > 0) {
    const double step = parameter_step(nodes_.back().point, p);
    // A block to the same point adds no span and no spline point.
    if (step < kSplineSamePoint) return;
    nodes_.push_back({p, block, step});
  } else {
    nodes_.push_back({p, block, 0.0});
  }
  update_tangents();
  emit_ready();
}

void HermiteSplineBuilder::finish(const SplineEnd& end) {
  if (finished_) return;
  finished_ = true;
  end_ = end;
  if (count() >= 2) update_tangents();
  emit_ready();
}

void HermiteSplineBuilder::copy_window(size_t lo, size_t hi, std::vector<Vec3>& points,
                                       std::vector<double>& steps) const {
  points.resize(hi - lo + 1);
  steps.resize(hi - lo);
  auto it = nodes_.begin() + static_cast<std::ptrdiff_t>(lo - first_);
  points[0] = it->point;
  for (size_t k = 1; k <= hi - lo; ++k) {
    ++it;
    points[k] = it->point;
    steps[k - 1] = it->step;
  }
}

bool HermiteSplineBuilder::pop_span(SplineSpan& out) {
  if (ready_.empty()) return false;
  out = std::move(ready_.front());
  ready_.pop_front();
  return true;
}

void HermiteSplineBuilder::emit_ready() {
  while (next_span_ < count() && node(next_span_ - 1).has_tangent && node(next_span_).has_tangent) {
    const Node& a = node(next_span_ - 1);
    const Node& b = node(next_span_);
    auto span = std::make_shared<PolynomialSpan>(
        PolynomialSpan::hermite(a.point, b.point, a.tangent, b.tangent, b.step));
    if (measure_spans_now_) span->length();
    ready_.push_back({std::move(span), b.block});
    ++next_span_;
  }
  const size_t keep = std::min(next_span_ - 1, needed_from());
  while (first_ < keep && !nodes_.empty()) {
    nodes_.pop_front();
    ++first_;
  }
}

}  // namespace drycut::geometry
