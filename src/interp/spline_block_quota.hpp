#pragma once
// The minimum-spline-blocks rule (facts §1.2): the control builds splines over a 10-block buffer
// and within every window of 10 blocks at least A: 4, B: 6, C: MD20160+1 must be spline end-point
// blocks. Blocks the loader consumes (comments, arithmetic, jumps) never reach here, so they do not
// count, as on the control.
#include <bitset>
#include <cstddef>

namespace drycut::interp {

class SplineBlockQuota {
 public:
  static constexpr size_t kWindow = 10;

  // Starts counting for a new spline mode with the quota for its type.
  void start(int required_per_window) {
    required_ = required_per_window;
    count_ = 0;
    window_.reset();
  }
  void stop() { required_ = 0; }
  bool active() const { return required_ > 0; }

  // Records one executed block; returns false when a spline point arrives and the window of 10
  // blocks that ends with it holds fewer spline end-point blocks than required. Windows that end
  // in non-spline blocks are not judged: after the last point of a run (its M17, a G40 before
  // the next G1) the buffer has nothing left to compute, and the experiment's programs, which end
  // their runs that way, ran on the real control.
  bool record(bool is_spline_point) {
    if (!active()) return true;
    window_ <<= 1;
    window_[0] = is_spline_point;
    if (count_ < kWindow) ++count_;
    if (count_ < kWindow || !is_spline_point) return true;
    return static_cast<int>(window_.count()) >= required_;
  }
  int required() const { return required_; }
  int in_window() const { return static_cast<int>(window_.count()); }

 private:
  int required_ = 0;
  size_t count_ = 0;
  std::bitset<kWindow> window_;
};

}  // namespace drycut::interp
