#include "report/svg_decimator.hpp"

#include <algorithm>

namespace drycut::report {

PointDecimator::PointDecimator(size_t max_buckets) : max_buckets_(std::max<size_t>(max_buckets, 2)) {
  buckets_.reserve(max_buckets_ + 1);
}

PointDecimator::Bucket PointDecimator::merge(const Bucket& a, const Bucket& b) {
  Bucket m;
  m.lo = b.lo.p.value < a.lo.p.value ? b.lo : a.lo;
  m.hi = b.hi.p.value > a.hi.p.value ? b.hi : a.hi;
  m.members = a.members + b.members;
  return m;
}

void PointDecimator::add(const PlotPoint& p) {
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
  if (buckets_.size() > max_buckets_) {
    // Halve: neighbours merge, so every bucket again covers `stride` points (the last may be partial).
    std::vector<Bucket> merged;
    merged.reserve(max_buckets_ + 1);
    for (size_t i = 0; i + 1 < buckets_.size(); i += 2) merged.push_back(merge(buckets_[i], buckets_[i + 1]));
    if (buckets_.size() % 2 == 1) merged.push_back(buckets_.back());
    buckets_ = std::move(merged);
    stride_ *= 2;
  }
}

std::vector<PlotPoint> PointDecimator::points() const {
  std::vector<PlotPoint> out;
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

}  // namespace drycut::report
