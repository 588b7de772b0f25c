#include "interp/spline_run.hpp"

#include <cstddef>
#include <type_traits>
#include <utility>

namespace drycut::interp {

void SplineRun::begin(MotionMode mode, const geometry::Vec3& start,
                      const geometry::SplineEnd& begin_condition, int degree, int cubic_window) {
  mode_ = mode;
  switch (mode) {
    case MotionMode::ASpline: builder_ = geometry::make_akima_builder(begin_condition); break;
    case MotionMode::CSpline: builder_ = geometry::make_cubic_builder(begin_condition, cubic_window); break;
    default: builder_ = geometry::make_nurbs_builder(degree); break;
  }
  clear_waiting();
  first_waiting_ = 1;
  next_index_ = 0;
  has_last_tangent_ = false;
  start_ = start;
}

void SplineRun::add(const geometry::Vec3& point, double weight, double knot_span, PathElement&& element) {
  if (next_index_ == 0) {
    // The start point is the current position, a control point nobody gave a weight: it takes
    // the first block's PW, so that equal weights on every block give the plain B-spline (the
    // experiment's PW=3 on every knot changes nothing) [inference, facts §1.5].
    builder_->add_point(start_, weight, 0.0);
    next_index_ = 1;
  }
  waiting_.push_back(std::move(element));
  builder_->add_point(point, weight, knot_span);
  ++next_index_;
}

void SplineRun::finish(const geometry::SplineEnd& end_condition) { builder_->finish(end_condition); }

void SplineRun::drain(ElementSink& sink) {
  geometry::SplineSpan span;
  while (builder_->pop_span(span)) {
    // Blocks whose spans are all out (a NURBS block may own none) leave the queue.
    size_t index = span.block_index < first_waiting_ ? first_waiting_ : span.block_index;
    while (first_waiting_ < index && waiting_count() > 1) {
      pop_waiting();
      ++first_waiting_;
    }
    // A block owns at most one span (spline_builder.hpp), so its template is moved, not copied
    // (the block text and label allocations per span): the next span belongs to a later block.
    PathElement element = std::move(waiting_[waiting_head_]);
    element.kind = ElementKind::SplineSpan;
    element.curve = std::move(span.curve);
    last_tangent_ = element.curve->end_tangent();
    has_last_tangent_ = true;
    sink.consume(std::move(element));
  }
}

void SplineRun::reset() {
  builder_.reset();
  clear_waiting();
}

// The waiting vector moves its elements when it grows or compacts (copies would cost more).
static_assert(std::is_nothrow_move_constructible_v<PathElement>);

void SplineRun::pop_waiting() {
  ++waiting_head_;
  // Compacted once the popped entries are many and at least half: amortised O(1), and the
  // vector's capacity stays small (a spline run keeps one or two blocks waiting).
  if (waiting_head_ >= 64 && 2 * waiting_head_ >= waiting_.size()) {
    waiting_.erase(waiting_.begin(), waiting_.begin() + static_cast<std::ptrdiff_t>(waiting_head_));
    waiting_head_ = 0;
  }
}

}  // namespace drycut::interp
