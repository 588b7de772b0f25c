#pragma once
// Everything the HTML report plots, gathered while the plan streams. Every series goes through a
// PointDecimator, so memory and file size stay bounded for any program length.
//
// Feed to plot:  interpreter -> on_programmed -> compensation -> on_tool_centre -> planner
//                planner observer -> on_block / on_sample (this class is a PlanObserver).
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "interp/path_element.hpp"
#include "motion/plan_result.hpp"
#include "report/svg_decimator.hpp"
#include "report/trace_3d_collector.hpp"

namespace drycut::report {

// Where a listed feed dip happened (found for the worst dips only).
struct DipLocation {
  bool known = false;
  double x = 0, y = 0, t = 0, s = 0;
};

struct RunPlots {
  std::vector<PlotPoint> tool_path;        // IPO samples: x, y, t, s (tool-centre arc length), v
  std::vector<PlotPoint> programmed_path;  // x, y, s (programmed arc length), value = deviation
  std::vector<PlotPoint> knots;            // programmed end points of cutting blocks
  uint64_t knot_count = 0;                 // all of them (knots holds every knot_stride-th)
  size_t knot_stride = 1;
  std::vector<PlotPoint> feed;             // programmed F (v) over t and s; v = NaN between runs
  bool has_deviation = false;
  double max_deviation_mm = 0;
  double programmed_length_mm = 0;
  uint64_t samples = 0;
  Trace3d trace;                           // the 3D viewer's trace (x, y, z, t, v, block)
};

struct RunPlotOptions {
  size_t buckets = 2000;  // per series: at most 2 × buckets + 2 points
  // Distance in the XY plane from a point to the reference contour; empty = no deviation plot.
  std::function<double(double x, double y)> distance_to_reference;
  // Elements whose both ends lie further than this from the reference are lead-ins/outs, not
  // contour, and get no deviation.
  double on_contour_mm = 1.0;
  double programmed_step_mm = 0.05;  // sampling of the programmed path for the deviation
  size_t trace_buckets = 4000;       // 3D trace: at most 2 × trace_buckets + 2 points
};

class RunPlotCollector : public motion::PlanObserver {
 public:
  explicit RunPlotCollector(RunPlotOptions options = {});

  void on_programmed(const interp::PathElement& element);
  void on_tool_centre(const interp::PathElement& element);
  void on_block(const motion::BlockTiming& timing) override;
  void on_sample(const motion::TrajectorySample& sample) override;

  RunPlots plots() const;
  // The location of a dip of the summary (matched by block and lowest velocity).
  DipLocation locate(const motion::FeedDip& dip) const;

 private:
  struct Pending {  // a tool-centre element the planner has not timed yet
    double feed = 0;
    bool cutting = false;
    double end_x = 0, end_y = 0;
    uint32_t line = 0;
    std::string label;
  };
  struct Candidate {
    double ratio = 0;  // lowest velocity / programmed F
    DipLocation where;
  };
  using BlockKey = std::pair<std::string, uint32_t>;
  void close_feed_run();
  void note_candidate(const motion::BlockTiming& timing, const Pending& element);

  RunPlotOptions options_;
  PointDecimator tool_path_, programmed_, knots_, feed_;
  Trace3dCollector trace_;
  std::deque<Pending> pending_;
  double clock_s_ = 0, length_mm_ = 0;  // committed totals
  // Current run of one programmed F.
  bool run_open_ = false;
  double run_feed_ = 0, run_t0_ = 0, run_s0_ = 0, run_t1_ = 0, run_s1_ = 0;
  // Samples: chord length along the tool-centre path, lowest sample of the current element.
  bool have_sample_ = false;
  double last_x_ = 0, last_y_ = 0, last_z_ = 0, sample_s_ = 0;
  bool element_has_min_ = false;
  DipLocation element_min_;
  double element_min_v_ = 0;
  uint64_t samples_ = 0;
  // Programmed path.
  double programmed_s_ = 0;
  bool has_deviation_ = false;
  double max_deviation_ = 0;
  // Bounded store of the worst-dipping blocks, to place the dips of the summary.
  std::map<BlockKey, Candidate> candidates_;
  std::set<std::pair<double, BlockKey>> by_ratio_;
  static constexpr size_t kMaxCandidates = 4096;
};

}  // namespace drycut::report
