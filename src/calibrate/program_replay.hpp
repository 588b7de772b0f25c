#pragma once
// One measured program, recorded once and re-planned for every trial profile.
//
// The interpreter and the tool radius compensation do not read the dynamic data a calibration
// varies (profile_fields.hpp), so the tool-centre element stream a program produces is the same
// for every trial: `RecordedProgram` keeps it, and `predict` hands a copy to a fresh Planner with
// the trial profile. That is the pipeline `drycut run` uses after the compensation stage, without
// parsing, interpreting and compensating the program again (the planner is most of the
// remaining cost). Elements share their curves; a program is re-planned by one thread at a time.
// Exception: under G641..G645 the corner-smoothing stage (interp/corner_smoothing.hpp) decides
// where to round from the dynamics of the profile the program was recorded with; a calibration
// of such programs keeps those decisions (docs/calibrate.md). The reference experiment runs G64.
#include <optional>
#include <string>
#include <vector>

#include "calibrate/measurements.hpp"
#include "interp/path_element.hpp"
#include "machine/machine_profile.hpp"

namespace drycut::calibrate {

struct RecordedProgram {
  std::string main_file;  // as the loader was given it (the file name of the main program's blocks)
  std::vector<interp::PathElement> elements;
};

// Collects the element stream (an ElementSink at the end of the pipeline).
class RecordingSink : public interp::ElementSink {
 public:
  explicit RecordingSink(RecordedProgram& out) : out_(out) {}
  void consume(interp::PathElement&& element) override { out_.elements.push_back(std::move(element)); }

 private:
  RecordedProgram& out_;
};

struct Prediction {
  std::optional<double> time_s;           // the run's span (none when the run does not reach an event)
  std::optional<double> min_feed_mm_min;  // lowest contour feed in the span / window (none: no motion there)
};

// Plans the recorded program on `profile` and measures what the run's measurement measures.
Prediction predict(const RecordedProgram& program, const machine::MachineProfile& profile, const report::RunSpan& span,
                   const std::optional<FeedWindow>& window);

}  // namespace drycut::calibrate
