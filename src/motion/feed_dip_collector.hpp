#pragma once
// Collects feed dips: consecutive cutting elements whose velocity fell below a share of their
// programmed F merge into one dip; at most `max_dips` are kept, the rest are only counted, so
// memory stays bounded for any program length.
#include <array>
#include <optional>
#include <vector>

#include "motion/plan_result.hpp"

namespace drycut::motion {

class FeedDipCollector {
 public:
  FeedDipCollector(double threshold, size_t max_dips) : threshold_(threshold), max_dips_(max_dips) {}

  // A committed cutting element of `length_mm`; v_min is its lowest velocity outside planned
  // standstills, in the programmed block `at` (the element's own source, or a block inside a
  // compressed span).
  void add(const BlockRef& source, const BlockRef& at, double programmed_feed, double v_min, Limit limit,
           double length_mm);
  // Anything that is not cutting (rapid, dwell, stop) ends the current stretch.
  void interrupt();

  const std::vector<FeedDip>& dips() const { return dips_; }
  size_t not_listed() const { return not_listed_; }

 private:
  void add_length(FeedDip& dip, Limit limit, double length_mm);  // and the dip's main limit

  double threshold_;
  size_t max_dips_;
  std::vector<FeedDip> dips_;
  size_t not_listed_ = 0;
  bool open_ = false;        // the last element dipped
  bool open_listed_ = false; // ... and its dip is in dips_
  std::array<double, kLimitCount> open_lengths_{};  // the open dip's length per element limit
};

}  // namespace drycut::motion
