#pragma once
// Knot-density sweep: for a method, the fewest knots at equal arc length over the whole closed
// curve (not per quadrant, so any count is possible) whose interpolated programmed contour stays
// within a tolerance of the curve.
//
// What is judged: the 2-D single-loop program at Z = -depth (EXPERIMENT.md §5) with
// `overlap_knots` knots repeated before and after the seam, run through the interpreter; the
// deviation is the maximum normal deviation over the full loop (seam to seam, so the seam is
// INCLUDED; the overlap hides the end effects of the spline as the experiment did). Search:
// doubling from min_knots to a passing count, bisection, then the neighbourhood below the answer
// is checked because the deviation of splines is not strictly monotone in the knot count.
#include <filesystem>
#include <functional>
#include <optional>
#include <vector>

#include "machine/machine_profile.hpp"
#include "workload/deviation_reference.hpp"
#include "workload/spline_program_writer.hpp"

namespace drycut::workload {

struct SweepOptions {
  double tolerance_mm = 0.08;
  int overlap_knots = 3;
  double sample_step_mm = 0.01;
  int min_knots = 4;
  int max_knots = 8192;
  int neighbourhood = 4;   // counts below the bisection answer that are checked too
};

struct SweepEvaluation {
  int knots = 0;
  double max_deviation_mm = 0.0;  // infinity when the program raised an alarm
};

struct SweepResult {
  Method method = Method::Linear;
  bool found = false;
  int knots = 0;                  // knots per loop
  double max_deviation_mm = 0.0;
  double spacing_mm = 0.0;        // arc length between knots
  size_t main_bytes = 0, sub_bytes = 0;  // the 3-D program at that density
  std::optional<double> time_after_m0_s;
  bool monotone = true;           // false: a count below the bisection answer passed too
  std::vector<SweepEvaluation> evaluations;  // in the order made
};

// Predicts the time of a generated 3-D program (the app plugs in the planner; the workload
// library does not depend on it). Returns nullopt when it cannot (alarm).
using TimePredictor = std::function<std::optional<double>(const std::filesystem::path& main_program)>;

// Max normal deviation of the full loop of the 2-D program with `knots` knots.
double loop_deviation(const CurveSource& curve, const ReferenceContour& reference, Method method, int knots,
                      const SweepOptions& options, const machine::MachineProfile& profile,
                      const std::filesystem::path& work_dir);

SweepResult sweep_method(const CurveSource& curve, Method method, const SweepOptions& options,
                         const machine::MachineProfile& profile, const TimePredictor& predict_time);

}  // namespace drycut::workload
