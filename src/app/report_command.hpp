#pragma once
// What `drycut report` and `drycut compare` share: one run through the whole pipeline with the
// plot collector tapped in, and the optional reference contour.
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "app/curve_options.hpp"
#include "app/program_pipeline.hpp"
#include "motion/plan_result.hpp"
#include "report/html_run_plots.hpp"
#include "workload/deviation_reference.hpp"

namespace drycut::app {

struct ReferenceContour {
  // The deviation module's contour (the same XY normal distance `drycut deviation` reports).
  std::shared_ptr<const workload::ReferenceContour> contour;
  std::vector<std::pair<double, double>> outline;  // for drawing (about 1000 points)
  std::string name;
};

// The reference contour when a curve option (--polar, --parametric, --points) is given.
std::optional<ReferenceContour> make_reference(const CurveOptions& options);

struct ReportRun {
  PipelineOutcome outcome;
  motion::PlanSummary summary;
  report::RunPlots plots;
  std::vector<report::DipLocation> dip_locations;  // parallel to summary.dips
  std::string machine;
};

// Runs loader -> interpreter -> compensation -> planner, collecting the plots. `samples`: plan
// with IPO samples (velocity plots); without them only the programmed path is collected.
ReportRun run_for_report(const ProgramOptions& options, const machine::MachineProfile& profile,
                         const ReferenceContour* reference, bool samples);

// Bytes of the main program plus every subprogram the run used (found as the loader finds them).
uint64_t program_bytes(const ProgramOptions& options, const std::vector<std::string>& programs_used);

}  // namespace drycut::app
