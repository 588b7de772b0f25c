#include "calibrate/program_replay.hpp"

#include <algorithm>
#include <limits>

#include "motion/planner.hpp"
#include "report/run_events.hpp"
#include "report/trace_csv_writer.hpp"

namespace drycut::calibrate {
namespace {

bool ends_with_nocase(const std::string& s, const std::string& suffix) {
  if (suffix.size() > s.size()) return false;
  for (size_t i = 0; i < suffix.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(s[s.size() - suffix.size() + i])) !=
        std::tolower(static_cast<unsigned char>(suffix[i])))
      return false;
  return true;
}

// Every planned block with its clock interval, lowest velocity and place in the feed window.
class BlockLog : public motion::PlanObserver {
 public:
  explicit BlockLog(const std::optional<FeedWindow>& window) : window_(window) {}
  void on_block(const motion::BlockTiming& t) override {
    Entry e{clock_, clock_ + t.time_s, t.v_min_mm_s, t.rapid || t.length_mm <= 0, -1};
    clock_ += t.time_s;
    if (window_ && ends_with_nocase(t.source.file_name(), window_->file_suffix)) {
      e.window_index = counter_++;
      if (!window_->between.empty() && t.source.text.find(window_->between) != std::string::npos) {
        if (!first_mark_) first_mark_ = e.window_index;
        last_mark_ = e.window_index;
      }
    }
    entries_.push_back(e);
  }

  // Lowest velocity (mm/s) of the moving blocks overlapping [from, to] and, with a window, in it.
  std::optional<double> lowest(double from, double to) const {
    double v = std::numeric_limits<double>::infinity();
    for (const Entry& e : entries_) {
      // Standstill (a start, an exact stop, the end) is not a feed the display shows while cutting.
      if (e.passive || e.v_min <= 1e-9 || e.t1 < from || e.t0 > to) continue;
      if (window_ && !in_window(e)) continue;
      v = std::min(v, e.v_min);
    }
    if (v == std::numeric_limits<double>::infinity()) return std::nullopt;
    return v;
  }

 private:
  struct Entry {
    double t0, t1, v_min;
    bool passive;
    long window_index;  // -1: not from a window file
  };
  bool in_window(const Entry& e) const {
    if (e.window_index < 0) return false;
    if (window_->between.empty()) return true;
    // After the first marked block, up to and including the last one (seam to seam).
    return first_mark_ && e.window_index > *first_mark_ && e.window_index <= last_mark_;
  }

  const std::optional<FeedWindow>& window_;
  std::vector<Entry> entries_;
  double clock_ = 0;
  long counter_ = 0;
  std::optional<long> first_mark_;
  long last_mark_ = -1;
};

}  // namespace

Prediction predict(const RecordedProgram& program, const machine::MachineProfile& profile, const report::RunSpan& span,
                   const std::optional<FeedWindow>& window) {
  report::RunEventRecorder events(program.main_file);
  BlockLog log(window);
  report::PlanObserverPair observers(events, log);
  motion::Planner planner(profile, observers);
  for (const auto& e : program.elements) planner.consume(interp::PathElement(e));  // a copy: kept for the next trial
  planner.finish();
  Prediction out;
  out.time_s = events.span_s(span);
  const auto from = events.time_of(span.from);
  const auto to = events.time_of(span.to);
  if (from && to) {
    if (auto v = log.lowest(*from, *to)) out.min_feed_mm_min = *v * 60.0;
  }
  return out;
}

}  // namespace drycut::calibrate
