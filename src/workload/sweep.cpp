#include "workload/sweep.hpp"

#include <atomic>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <string>

#include <unistd.h>

#include "machine/alarm.hpp"
#include "workload/deviation_passes.hpp"
#include "workload/deviation_program_run.hpp"

namespace drycut::workload {
namespace {

void write_file(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out) throw UsageError("cannot write " + path.string());
}

ProgramSpec spec_for(const CurveSource& curve, Method method, MillingMode mode, int overlap) {
  ProgramSpec spec;
  spec.method = method;
  spec.mode = mode;
  spec.main_name = "SWEEP";
  spec.sub_name = "SWEEP_SUB";
  spec.overlap_knots = overlap;
  spec.feed_mm_min = mode == MillingMode::Progressive3D ? 1530 : 1270;
  spec.entry_point = curve.point(curve.t_end - spec.entry_angle_rad);
  return spec;
}

// A private scratch folder, removed when the sweep ends.
class ScratchDir {
 public:
  ScratchDir() {
    static std::atomic<int> counter{0};
    path_ = std::filesystem::temp_directory_path() /
            ("drycut_sweep_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
    std::filesystem::create_directories(path_);
  }
  ~ScratchDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace

double loop_deviation(const CurveSource& curve, const ReferenceContour& reference, Method method, int knots,
                      const SweepOptions& options, const machine::MachineProfile& profile,
                      const std::filesystem::path& work_dir) {
  const auto program = write_contour_program(equal_arc_knots(curve, knots), curve.t_end - curve.t_begin,
                                             spec_for(curve, method, MillingMode::Loop2D, options.overlap_knots));
  write_file(work_dir / "SWEEP.MPF", program.main_text);
  write_file(work_dir / "SWEEP_SUB.SPF", program.sub_text);
  SampleOptions sample_options;
  sample_options.step_mm = options.sample_step_mm;
  sample_options.tool_centre = false;
  const SampledProgram sampled = sample_program(work_dir / "SWEEP.MPF", profile, sample_options);
  if (sampled.program_alarm) return std::numeric_limits<double>::infinity();
  const ContourSplit split = split_contour(sampled, reference);
  double worst = 0.0;
  bool any_loop = false;
  for (const ContourPass& pass : split.passes) {
    if (!pass.full_loop) continue;
    any_loop = true;
    for (const Vec3& p : pass.programmed) worst = std::max(worst, reference.nearest(Vec2(p.x(), p.y())).distance);
  }
  return any_loop ? worst : std::numeric_limits<double>::infinity();
}

SweepResult sweep_method(const CurveSource& curve, Method method, const SweepOptions& options,
                         const machine::MachineProfile& profile, const TimePredictor& predict_time) {
  if (!(options.tolerance_mm > 0)) throw UsageError("the tolerance must be > 0");
  if (options.min_knots < 3 || options.max_knots < options.min_knots) throw UsageError("bad knot range");
  const ReferenceContour reference(curve);
  ScratchDir scratch;
  SweepResult result;
  result.method = method;
  std::map<int, double> seen;
  auto deviation = [&](int n) {
    auto it = seen.find(n);
    if (it != seen.end()) return it->second;
    const double d = loop_deviation(curve, reference, method, n, options, profile, scratch.path());
    seen[n] = d;
    result.evaluations.push_back({n, d});
    return d;
  };
  auto passes = [&](int n) { return deviation(n) <= options.tolerance_mm; };

  // Doubling to a passing count, then bisection on [fail, pass].
  int low = options.min_knots, high = options.min_knots;
  if (!passes(low)) {
    while (true) {
      if (high >= options.max_knots) return result;  // not found within the range
      low = high;
      high = std::min(2 * high, options.max_knots);
      if (passes(high)) break;
    }
    while (high - low > 1) {
      const int mid = low + (high - low) / 2;
      (passes(mid) ? high : low) = mid;
    }
  }
  // The neighbourhood below: a passing count there means the deviation is not monotone; take the
  // smallest count from which every checked count up to the answer passes.
  int answer = high;
  for (int n = high - 1; n >= std::max(options.min_knots, high - options.neighbourhood); --n) {
    if (passes(n)) {
      result.monotone = false;
      answer = n;
    } else {
      break;
    }
  }
  for (int n = high - 1; n >= std::max(options.min_knots, high - options.neighbourhood); --n)
    if (n < answer && passes(n)) result.monotone = false;

  result.found = true;
  result.knots = answer;
  result.max_deviation_mm = deviation(answer);
  result.spacing_mm = reference.length() / answer;
  const auto program3d = write_contour_program(equal_arc_knots(curve, answer), curve.t_end - curve.t_begin,
                                               spec_for(curve, method, MillingMode::Progressive3D, 0));
  result.main_bytes = program3d.main_text.size();
  result.sub_bytes = program3d.sub_text.size();
  if (predict_time) {
    write_file(scratch.path() / "SWEEP.MPF", program3d.main_text);
    write_file(scratch.path() / "SWEEP_SUB.SPF", program3d.sub_text);
    result.time_after_m0_s = predict_time(scratch.path() / "SWEEP.MPF");
  }
  return result;
}

}  // namespace drycut::workload
