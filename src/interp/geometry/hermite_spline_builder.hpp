#pragma once
// Shared streaming machinery of the interpolating splines (A and C): distinct points with their
// chord-length steps, a tangent per point filled in by the concrete method, and one cubic
// Hermite span per pair of consecutive points once both tangents are known. Points no longer
// needed are dropped, so memory stays bounded by the method's look-ahead.
#include <deque>
#include <vector>

#include "interp/geometry/spline_builder.hpp"

namespace drycut::geometry {

class HermiteSplineBuilder : public SplineBuilder {
 public:
  void add_point(const Vec3& p, double weight, double knot_span) final;
  void finish(const SplineEnd& end) final;
  bool pop_span(SplineSpan& out) final;

 protected:
  struct Node {
    Vec3 point;
    size_t block = 0;   // add_point index
    double step = 0.0;  // chord-length parameter step from the previous node (0 for node 0)
    Vec3 tangent = Vec3::Zero();
    bool has_tangent = false;
  };

  // measure_spans_now: build each span's arc-length table as it is made (on the interpreting
  // thread) rather than when the planner first measures it. Which thread should carry that cost
  // is a balance of the pipeline's two threads (callgrind, instructions per block, 100 k-block
  // programs): Akima's tangents are cheap, so its interpreting thread is the shorter one and
  // builds the table; the C-spline's windowed solves make its interpreting thread the longer one.
  explicit HermiteSplineBuilder(bool measure_spans_now) : measure_spans_now_(measure_spans_now) {}

  // Sets every tangent that has become final (all remaining ones once finished()).
  virtual void update_tangents() = 0;
  // Lowest node index the method will still read.
  virtual size_t needed_from() const = 0;

  size_t count() const { return first_ + nodes_.size(); }  // distinct points so far
  Node& node(size_t i) { return nodes_[i - first_]; }
  const Node& node(size_t i) const { return nodes_[i - first_]; }
  // Points lo..hi into `points` and the steps of lo+1..hi into `steps` (a window's linear
  // system; walked by deque iterator, not indexed per node).
  void copy_window(size_t lo, size_t hi, std::vector<Vec3>& points, std::vector<double>& steps) const;
  bool finished() const { return finished_; }
  const SplineEnd& end_condition() const { return end_; }

 private:
  void emit_ready();

  std::deque<Node> nodes_;
  size_t first_ = 0;        // node index of nodes_.front()
  size_t next_block_ = 0;   // add_point calls so far
  size_t next_span_ = 1;    // node index of the end point of the next span to build
  bool finished_ = false;
  bool measure_spans_now_;
  SplineEnd end_;
  std::deque<SplineSpan> ready_;
};

}  // namespace drycut::geometry
