#pragma once
// Streaming decimation for plots: any number of points go in, at most 2 × max_buckets come out,
// memory stays bounded. Consecutive points are grouped in buckets of `stride` points; each bucket
// keeps the point with the lowest and the one with the highest `value`, so a one-sample feed dip
// survives decimation. When the buckets run out, neighbours merge pairwise and the stride doubles.
// A template over the point type (anything with a `double value`): the 2D plots and the 3D
// trace of the report keep different fields per point but decimate alike.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace drycut::report {

// One plotted point; which fields mean something depends on the series.
struct PlotPoint {
  double x = 0, y = 0;  // mm, top view
  double t = 0;         // s
  double s = 0;         // arc length, mm
  double v = 0;         // mm/s (velocity, or programmed F for the feed series)
  double value = 0;     // the quantity whose extremes survive decimation
};

template <class Point>
class ExtremaDecimator {
 public:
  explicit ExtremaDecimator(size_t max_buckets = 2500) : max_buckets_(std::max<size_t>(max_buckets, 2)) {
    buckets_.reserve(max_buckets_ + 1);
  }

  void add(const Point& p) {
    const Indexed in{p, count_++};
    if (in.index == 0) first_ = in;
    last_ = in;
    if (buckets_.empty() || buckets_.back().members >= stride_) {
      buckets_.push_back(Bucket{in, in, 1});
    } else {
      Bucket& b = buckets_.back();
      if (p.value < b.lo.p.value) b.lo = in;
      if (p.value > b.hi.p.value) b.hi = in;
      ++b.members;
    }
    if (buckets_.size() > max_buckets_) halve();
  }

  // The kept points in input order, the very first and last input point included.
  std::vector<Point> points() const {
    std::vector<Point> out;
    if (count_ == 0) return out;
    out.reserve(2 * buckets_.size() + 2);
    uint64_t last_index = 0;
    bool any = false;
    auto push = [&](const Indexed& i) {
      if (any && i.index <= last_index) return;
      out.push_back(i.p);
      last_index = i.index;
      any = true;
    };
    push(first_);  // a path starts where it starts, whatever its extremes
    for (const Bucket& b : buckets_) {
      if (b.lo.index <= b.hi.index) {
        push(b.lo);
        push(b.hi);
      } else {
        push(b.hi);
        push(b.lo);
      }
    }
    push(last_);
    return out;
  }
  uint64_t count() const { return count_; }
  size_t stride() const { return stride_; }
  // Most points points() can return.
  size_t capacity() const { return 2 * max_buckets_ + 2; }

 private:
  struct Indexed {
    Point p;
    uint64_t index = 0;
  };
  struct Bucket {
    Indexed lo, hi;
    size_t members = 0;
  };
  static Bucket merge(const Bucket& a, const Bucket& b) {
    Bucket m;
    m.lo = b.lo.p.value < a.lo.p.value ? b.lo : a.lo;
    m.hi = b.hi.p.value > a.hi.p.value ? b.hi : a.hi;
    m.members = a.members + b.members;
    return m;
  }
  // Neighbours merge, so every bucket again covers `stride` points (the last may be partial).
  void halve() {
    std::vector<Bucket> merged;
    merged.reserve(max_buckets_ + 1);
    for (size_t i = 0; i + 1 < buckets_.size(); i += 2) merged.push_back(merge(buckets_[i], buckets_[i + 1]));
    if (buckets_.size() % 2 == 1) merged.push_back(buckets_.back());
    buckets_ = std::move(merged);
    stride_ *= 2;
  }

  size_t max_buckets_;
  size_t stride_ = 1;
  uint64_t count_ = 0;
  std::vector<Bucket> buckets_;
  Indexed first_, last_;
};

using PointDecimator = ExtremaDecimator<PlotPoint>;

}  // namespace drycut::report
