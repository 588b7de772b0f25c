#pragma once
// Whether the further axes (rotary A/C ...) of a compressor run can ride on its spans. A span
// carries the further axes of the blocks it replaces linearly along its path (their travels
// summed, block_compressor.hpp), so the run must hold their programmed positions on a straight
// line over path length within each axis's MD33100 COMPRESS_POS_TOL: a block that turns C by
// 8 deg/mm among blocks of 0.2 deg/mm, or `X20 A-40` among straight blocks, must not be averaged
// into its neighbours (before 2026-11-28 it was, and the planner then drove C at 800 deg/s
// against a 120 deg/s limit: the rate it saw was the span's average). Where the line cannot hold
// them the run is cut (the XY path stays tangent-continuous across the cut), so the planner
// sees each rate where the program has it.
//
// Algorithm (the "swing door" of piecewise-linear data compression), per axis, O(1) per block:
// from the stretch's start (path length s = 0, axis travel v = 0), a straight line v = r·s holds
// every programmed end point (s_k, v_k) within tol exactly when r lies in every interval
// [(v_k - tol)/s_k, (v_k + tol)/s_k]. Keep the intersection [lo, hi] of those intervals; a new
// block ending at (s, v) may join when r = v/s lies in [lo, hi] (the line through its end point
// holds all points before), and then narrows [lo, hi] by its own interval. A block of no path
// length that turns an axis by more than tol never joins (r would be infinite).
#include <vector>

#include "interp/path_element.hpp"
#include "machine/machine_profile.hpp"

namespace drycut::interp {

class ExtraAxisLinearity {
 public:
  explicit ExtraAxisLinearity(const machine::MachineProfile& profile) : profile_(profile) {}

  // A new stretch starts where the run (or its cut) is now.
  void restart();
  // Whether `e` (length `length` on the path) keeps every further axis on one line with the
  // stretch; when it does, it becomes part of the stretch.
  bool extend(const PathElement& e, double length);

 private:
  struct Door {
    double travel = 0.0;  // since the stretch's start
    double lo = 0.0, hi = 0.0;
    bool open = false;    // no point constrains it yet
  };
  double tolerance(size_t axis) const;

  const machine::MachineProfile& profile_;
  double length_ = 0.0;      // path length since the stretch's start
  std::vector<Door> doors_;  // per MachineProfile::extra_axes index
  std::vector<double> travel_;  // reused: this block's travel per axis
};

}  // namespace drycut::interp
