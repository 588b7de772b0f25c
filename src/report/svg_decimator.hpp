#pragma once
// Streaming decimation for plots: any number of points go in, at most 2 × max_buckets come out,
// memory stays bounded. Consecutive points are grouped in buckets of `stride` points; each bucket
// keeps the point with the lowest and the one with the highest `value`, so a one-sample feed dip
// survives decimation. When the buckets run out, neighbours merge pairwise and the stride doubles.
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

class PointDecimator {
 public:
  explicit PointDecimator(size_t max_buckets = 2500);

  void add(const PlotPoint& p);
  // The kept points in input order, the very first and last input point included.
  std::vector<PlotPoint> points() const;
  uint64_t count() const { return count_; }
  size_t stride() const { return stride_; }

 private:
  struct Indexed {
    PlotPoint p;
    uint64_t index = 0;
  };
  struct Bucket {
    Indexed lo, hi;
    size_t members = 0;
  };
  static Bucket merge(const Bucket& a, const Bucket& b);

  size_t max_buckets_;
  size_t stride_ = 1;
  uint64_t count_ = 0;
  std::vector<Bucket> buckets_;
  Indexed first_, last_;
};

}  // namespace drycut::report
