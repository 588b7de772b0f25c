#include "report/html_run_plots.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace drycut::report {
namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kDipShare = 0.8;  // as PlannerOptions::dip_threshold
}  // namespace

RunPlotCollector::RunPlotCollector(RunPlotOptions options)
    : options_(std::move(options)),
      tool_path_(options_.buckets),
      programmed_(options_.buckets),
      knots_(options_.buckets),
      feed_(options_.buckets),
      trace_(options_.trace_buckets) {}

void RunPlotCollector::on_programmed(const interp::PathElement& e) {
  if (!e.is_motion() || !e.curve) return;
  const geometry::Curve& c = *e.curve;
  const double length = c.length();
  if (!std::isfinite(length)) return;
  const geometry::Vec3 a = c.start(), b = c.end();
  const bool deviation = options_.distance_to_reference && !e.rapid &&
                         options_.distance_to_reference(a.x(), a.y()) <= options_.on_contour_mm &&
                         options_.distance_to_reference(b.x(), b.y()) <= options_.on_contour_mm;
  // Without a reference a few points per element draw it; with one, sample densely for the maximum.
  const double step = deviation ? options_.programmed_step_mm : std::max(options_.programmed_step_mm, length / 8);
  const int n = std::clamp(static_cast<int>(std::ceil(length / std::max(step, 1e-9))), 1, 100000);
  for (int i = (programmed_.count() == 0 ? 0 : 1); i <= n; ++i) {
    const double s = length * i / n;
    const geometry::Vec3 p = c.at(s).position;
    PlotPoint q{p.x(), p.y(), 0, programmed_s_ + s, 0, kNaN};
    if (deviation) {
      q.value = options_.distance_to_reference(p.x(), p.y());
      has_deviation_ = true;
      max_deviation_ = std::max(max_deviation_, q.value);
    } else {
      q.value = -1;  // a break in the deviation line, kept by the decimator as a low extreme
    }
    programmed_.add(q);
  }
  programmed_s_ += length;
  if (!e.rapid) knots_.add(PlotPoint{b.x(), b.y(), 0, programmed_s_, 0, 0});
}

void RunPlotCollector::on_tool_centre(const interp::PathElement& e) {
  trace_.on_tool_centre(e);
  Pending p;
  p.feed = e.feed_mm_s;
  p.cutting = e.is_motion() && !e.rapid && e.curve && e.curve->length() > 1e-9;
  if (e.is_motion() && e.curve) {
    const geometry::Vec3 end = e.curve->end();
    p.end_x = end.x();
    p.end_y = end.y();
  }
  p.line = e.source.line;
  p.label = e.label;
  pending_.push_back(std::move(p));
}

void RunPlotCollector::close_feed_run() {
  if (!run_open_) return;
  feed_.add(PlotPoint{0, 0, run_t0_, run_s0_, run_feed_, run_feed_});
  feed_.add(PlotPoint{0, 0, run_t1_, run_s1_, run_feed_, run_feed_});
  run_open_ = false;
}

void RunPlotCollector::on_block(const motion::BlockTiming& timing) {
  trace_.on_block(timing);
  // The planner times elements in the order it consumed them; skip any it never timed.
  while (!pending_.empty() && (pending_.front().line != timing.source.line || pending_.front().label != timing.label))
    pending_.pop_front();
  Pending element;
  if (!pending_.empty()) {
    element = pending_.front();
    pending_.pop_front();
  }
  const double t0 = clock_s_, s0 = length_mm_;
  clock_s_ += timing.time_s;
  length_mm_ += timing.length_mm;
  if (timing.length_mm > 0) {
    if (element.cutting && !timing.rapid) {
      if (!run_open_ || element.feed != run_feed_) {
        close_feed_run();
        run_open_ = true;
        run_feed_ = element.feed;
        run_t0_ = t0;
        run_s0_ = s0;
      }
      run_t1_ = clock_s_;
      run_s1_ = length_mm_;
      note_candidate(timing, element);
    } else if (run_open_) {
      close_feed_run();
      feed_.add(PlotPoint{0, 0, t0, s0, kNaN, -1});  // no F during rapids: break the line
    }
  }
  element_has_min_ = false;
}

void RunPlotCollector::note_candidate(const motion::BlockTiming& timing, const Pending& element) {
  // Exact-stop ends are planned standstills, not dips (the planner excludes them too).
  if (timing.limit == motion::Limit::ExactStop || !(element.feed > 0)) return;
  const double ratio = timing.v_min_mm_s / element.feed;
  if (!(ratio < kDipShare)) return;
  Candidate c;
  c.ratio = ratio;
  if (element_has_min_) {
    c.where = element_min_;
  } else {
    c.where = DipLocation{true, element.end_x, element.end_y, clock_s_, length_mm_};
  }
  BlockKey key{timing.source.file_name(), timing.source.line};
  auto it = candidates_.find(key);
  if (it != candidates_.end()) {
    if (it->second.ratio <= ratio) return;
    by_ratio_.erase({it->second.ratio, key});
    it->second = c;
    by_ratio_.insert({ratio, key});
    return;
  }
  if (candidates_.size() >= kMaxCandidates) {
    auto worst = std::prev(by_ratio_.end());  // the mildest dip goes
    if (worst->first <= ratio) return;
    candidates_.erase(worst->second);
    by_ratio_.erase(worst);
  }
  candidates_.emplace(key, c);
  by_ratio_.insert({ratio, std::move(key)});
}

void RunPlotCollector::on_sample(const motion::TrajectorySample& sample) {
  trace_.on_sample(sample);
  const double x = sample.position.x(), y = sample.position.y(), z = sample.position.z();
  if (have_sample_) sample_s_ += std::sqrt((x - last_x_) * (x - last_x_) + (y - last_y_) * (y - last_y_) + (z - last_z_) * (z - last_z_));
  have_sample_ = true;
  last_x_ = x, last_y_ = y, last_z_ = z;
  ++samples_;
  tool_path_.add(PlotPoint{x, y, sample.t_s, sample_s_, sample.v_mm_s, sample.v_mm_s});
  if (!element_has_min_ || sample.v_mm_s < element_min_v_) {
    element_has_min_ = true;
    element_min_v_ = sample.v_mm_s;
    element_min_ = DipLocation{true, x, y, sample.t_s, sample_s_};
  }
}

RunPlots RunPlotCollector::plots() const {
  RunPlots p;
  p.tool_path = tool_path_.points();
  p.programmed_path = programmed_.points();
  for (auto& q : p.programmed_path)
    if (q.value < 0) q.value = kNaN;
  p.knots = knots_.points();
  p.knot_count = knots_.count();
  p.knot_stride = knots_.stride();
  PointDecimator feed = feed_;
  if (run_open_) {
    feed.add(PlotPoint{0, 0, run_t0_, run_s0_, run_feed_, run_feed_});
    feed.add(PlotPoint{0, 0, run_t1_, run_s1_, run_feed_, run_feed_});
  }
  p.feed = feed.points();
  p.has_deviation = has_deviation_;
  p.max_deviation_mm = max_deviation_;
  p.programmed_length_mm = programmed_s_;
  p.samples = samples_;
  p.trace = trace_.trace();
  return p;
}

DipLocation RunPlotCollector::locate(const motion::FeedDip& dip) const {
  auto it = candidates_.find(BlockKey{dip.min_element.file_name(), dip.min_element.line});
  return it == candidates_.end() ? DipLocation{} : it->second.where;
}

}  // namespace drycut::report
