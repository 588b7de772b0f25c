#pragma once
// A run of consecutive spline blocks of one type, turned into path elements while streaming.
// The geometry builder sees the points; this class remembers, for each block still waiting for its
// spans, what the element needs besides geometry (source block, feed, dynamics, compensation). The
// builders are local (Akima, windowed cubic, NURBS), so the waiting queue stays short.
#include <memory>
#include <vector>

#include "interp/geometry/spline_builder.hpp"
#include "interp/modal_state.hpp"
#include "interp/path_element.hpp"

namespace drycut::interp {

class SplineRun {
 public:
  bool active() const { return builder_ != nullptr; }
  MotionMode mode() const { return mode_; }
  size_t points() const { return next_index_; }

  // Starts a run at the current position. `degree` is used by B splines only.
  void begin(MotionMode mode, const geometry::Vec3& start, const geometry::SplineEnd& begin_condition,
             int degree, int cubic_window);
  // Adds one programmed point; `element` carries everything but the geometry of its span(s).
  void add(const geometry::Vec3& point, double weight, double knot_span, PathElement&& element);
  // Ends the run with the given end condition.
  void finish(const geometry::SplineEnd& end_condition);
  // Hands every span that is final to the sink; returns the end tangent of the last one emitted.
  void drain(ElementSink& sink);
  // After finish() and drain(): forget the run.
  void reset();

  bool has_last_tangent() const { return has_last_tangent_; }
  const geometry::Vec3& last_tangent() const { return last_tangent_; }

 private:
  MotionMode mode_ = MotionMode::ASpline;
  std::unique_ptr<geometry::SplineBuilder> builder_;
  // Element templates of blocks first_waiting_.. in order: waiting_[waiting_head_..]. A vector
  // with a moving head, not a std::deque: a PathElement is larger than a deque block, so each
  // spline block cost a deque node malloc and free. Popped entries stay until pop_waiting()
  // compacts the vector (their memory only: nothing reads them).
  std::vector<PathElement> waiting_;
  size_t waiting_head_ = 0;
  size_t first_waiting_ = 1;  // block index of waiting_[waiting_head_] (point 0 is the start)

  size_t waiting_count() const { return waiting_.size() - waiting_head_; }
  void pop_waiting();
  void clear_waiting() {
    waiting_.clear();
    waiting_head_ = 0;
  }
  size_t next_index_ = 0;
  geometry::Vec3 start_ = geometry::Vec3::Zero();
  bool has_last_tangent_ = false;
  geometry::Vec3 last_tangent_ = geometry::Vec3::UnitX();
};

}  // namespace drycut::interp
