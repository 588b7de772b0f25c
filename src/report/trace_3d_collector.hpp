#pragma once
// The tool-centre trace for the report's 3D viewer, gathered while the plan streams: IPO samples
// in 3D with time, path velocity, the block they belong to and whether it is a rapid.
//
// Bounded for any program length: samples go through an ExtremaDecimator keyed on velocity (the
// lowest and highest sample of each stretch survive, so no dip disappears), and only the blocks
// that kept samples still refer to are remembered.
//
// Which element a sample belongs to: the planner emits an element's samples, then its timing
// (on_block), element after element in the order it consumed them. So the samples between the
// n-th and the (n+1)-th on_block belong to the (n+1)-th element, the front of the queue of
// tool-centre elements handed to the planner (on_tool_centre) and not yet timed.
#include <cstdint>
#include <deque>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "interp/path_element.hpp"
#include "motion/plan_result.hpp"
#include "report/svg_decimator.hpp"

namespace drycut::report {

struct TracePoint {
  double x = 0, y = 0, z = 0;  // tool centre, machine coordinates, mm
  double t = 0;                // s
  double v = 0;                // path velocity, mm/s
  double value = 0;            // = v: what the decimator keeps the extremes of
  uint64_t block = 0;          // sequence number of the executed block (index into Trace3d::blocks after trace())
  bool rapid = false;
};

struct TraceBlock {
  FileName file = nullptr;
  uint32_t line = 0;
  std::string text;
  double feed_mm_s = 0;  // programmed F handed to the planner (tool centre); 0 for rapids
  bool rapid = false;
};

struct Trace3d {
  std::vector<TracePoint> points;  // in time order; points[i].block indexes blocks
  std::vector<TraceBlock> blocks;  // the blocks the kept points belong to, in execution order
  uint64_t samples = 0;            // IPO samples before decimation
};

class Trace3dCollector {
 public:
  explicit Trace3dCollector(size_t buckets = 4000);
  Trace3dCollector(const Trace3dCollector&) = delete;  // holds a pointer into its own map
  Trace3dCollector& operator=(const Trace3dCollector&) = delete;

  void on_tool_centre(const interp::PathElement& element);
  void on_block(const motion::BlockTiming& timing);
  void on_sample(const motion::TrajectorySample& sample);

  Trace3d trace() const;

 private:
  struct Pending {
    uint32_t line = 0;
    std::string label;
    double feed_mm_s = 0;
    bool rapid = false;
  };
  void forget_unreferenced_blocks();

  std::deque<Pending> pending_;
  ExtremaDecimator<TracePoint> points_;
  std::unordered_map<uint64_t, TraceBlock> blocks_;  // by block sequence number
  uint64_t block_seq_ = 0;                           // on_block calls so far
  const TraceBlock* current_ = nullptr;              // the entry of block current_seq_
  uint64_t current_seq_ = 0;
  size_t prune_at_;
};

}  // namespace drycut::report
