#pragma once
// What the planner reports: one timing per element, optional samples per IPO cycle, feed dips
// and a summary.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "interp/geometry/curve.hpp"
#include "machine/source_location.hpp"
#include "motion/limit.hpp"

namespace drycut::motion {

using geometry::Vec3;

struct BlockTiming {
  BlockRef source;
  std::string label;
  double time_s = 0;
  double length_mm = 0;
  double v_max_mm_s = 0;  // highest velocity reached in the element
  double v_min_mm_s = 0;  // lowest velocity in the element (its ends included)
  Limit limit = Limit::Feed;  // the constraint that bound the LOWEST velocity in the element
  bool rapid = false;
  bool after_first_m0 = false;
  // A span of the NC block compressor: the programmed blocks it replaces (0: none) and how far
  // it strays from their programmed points and lines (interp::PathElement).
  uint32_t compressed_blocks = 0;
  double compress_deviation_mm = 0;
  // A corner-smoothing element (G641/G642/G643/G645): its closest distance to the programmed
  // corner it rounds; < 0 for every other element.
  double smoothing_deviation_mm = -1;
};

struct TrajectorySample {
  double t_s = 0;
  Vec3 position = Vec3::Zero();
  double v_mm_s = 0, a_mm_s2 = 0, j_mm_s3 = 0;  // along the path
  const BlockRef* source = nullptr;             // valid during on_sample only
  // Per-axis set-points derived from the path state and the curve geometry:
  // velocity v·t, acceleration a·t + v²·κ (κ = d²P/ds²).
  Vec3 tangent = Vec3::UnitX();
  Vec3 axis_velocity_mm_s = Vec3::Zero();
  Vec3 axis_accel_mm_s2 = Vec3::Zero();
};

class PlanObserver {
 public:
  virtual ~PlanObserver() = default;
  virtual void on_block(const BlockTiming&) {}
  virtual void on_sample(const TrajectorySample&) {}
};

// A stretch of consecutive cutting elements whose velocity fell below 80 % of the programmed F
// (ramps into and out of planned standstills do not count).
struct FeedDip {
  BlockRef source;               // first block of the stretch
  BlockRef min_source;           // block where the lowest velocity occurs
  BlockRef min_element;          // the element's own source there (a compressed span's first block)
  double v_min_mm_s = 0;
  double programmed_feed_mm_s = 0;  // F of the block at the minimum
  Limit limit = Limit::Feed;     // what bound the lowest velocity
  size_t element_count = 0;      // elements merged into this dip
  double length_mm = 0;          // path length of the merged elements
  // What bound the elements over most of that length (each element counts with the limit of its
  // own lowest velocity): a whole pass held down by the short-block rule, entered at a corner,
  // is a `corner` dip at its lowest point and a `short_block` stretch.
  Limit main_limit = Limit::Feed;
};

struct PlanSummary {
  double time_s = 0;
  double time_after_m0_s = 0;  // from the first element after the first M0 to the end; 0 if no M0
  double path_length_mm = 0;
  double min_feed_mm_s = 0;    // lowest velocity while cutting, planned standstills excluded
  double max_feed_mm_s = 0;
  std::vector<FeedDip> dips;   // at most PlannerOptions::max_dips
  size_t dips_not_listed = 0;  // dips beyond that bound
  size_t elements = 0;
};

struct PlannerOptions {
  bool emit_samples = false;  // IPO-cycle samples to observer.on_sample
  double dip_threshold = 0.8; // a dip: velocity below this share of the programmed F
  size_t max_dips = 1000;
  // Test references: cut every curved element into equal segments, of h = clamp(v_ref·T_IPO,
  // 0.01, 0.5) mm (the rule before element_discretisation.hpp), or of reference_segment_mm
  // when > 0, instead of the adaptive rule.
  bool reference_segments = false;
  double reference_segment_mm = 0;
};

}  // namespace drycut::motion
