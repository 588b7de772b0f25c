#include "motion/feed_dip_collector.hpp"

namespace drycut::motion {

void FeedDipCollector::add(const BlockRef& source, const BlockRef& at, double programmed_feed, double v_min, Limit limit,
                           double length_mm) {
  if (!(v_min < threshold_ * programmed_feed)) {
    interrupt();
    return;
  }
  if (open_) {
    if (open_listed_) {
      FeedDip& dip = dips_.back();
      ++dip.element_count;
      add_length(dip, limit, length_mm);
      if (v_min < dip.v_min_mm_s) {
        dip.v_min_mm_s = v_min;
        dip.min_source = at;
        dip.min_element = source;
        dip.programmed_feed_mm_s = programmed_feed;
        dip.limit = limit;
      }
    }
    return;
  }
  open_ = true;
  open_listed_ = dips_.size() < max_dips_;
  if (!open_listed_) {
    ++not_listed_;
    return;
  }
  dips_.push_back(FeedDip{source, at, source, v_min, programmed_feed, limit, 1, 0.0, limit});
  open_lengths_.fill(0.0);
  add_length(dips_.back(), limit, length_mm);
}

void FeedDipCollector::add_length(FeedDip& dip, Limit limit, double length_mm) {
  dip.length_mm += length_mm;
  double& by_limit = open_lengths_[static_cast<size_t>(limit)];
  by_limit += length_mm;
  if (by_limit > open_lengths_[static_cast<size_t>(dip.main_limit)]) dip.main_limit = limit;
}

void FeedDipCollector::interrupt() {
  open_ = false;
  open_listed_ = false;
}

}  // namespace drycut::motion
