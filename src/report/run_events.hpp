#pragma once
// Named instants of a planned run and the span between two of them (`drycut run --span FROM..TO`,
// the span `drycut experiment` compares with the measured times). Taken from the block timings
// the planner reports in order, so the clock is the planner's own (the sum of the block times):
//   start          0
//   after_m0       the end of the first M0 (the operator restarts there; M0 itself takes no time)
//   after_dwell    the end of the first dwell (G4) after after_m0; without an M0 the first dwell
//   contour_start  the start of the first block of the outermost subprogram call: the first
//                  planned block that comes from a file other than the main program
//   contour_end    the end of the last block of that call, before the main program goes on
//   end            the end of the last planned block (summary.time_s)
// An event the run does not reach (no M0, no dwell, no call, or a stop by an alarm before it)
// has no time, and neither has a span that names it.
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "motion/plan_result.hpp"

namespace drycut::report {

enum class RunEvent { Start, AfterM0, AfterDwell, ContourStart, ContourEnd, End };

inline constexpr std::array<RunEvent, 6> kRunEvents{RunEvent::Start,        RunEvent::AfterM0,
                                                    RunEvent::AfterDwell,   RunEvent::ContourStart,
                                                    RunEvent::ContourEnd,   RunEvent::End};

std::string_view event_name(RunEvent event);
std::optional<RunEvent> parse_event(std::string_view name);

struct RunSpan {
  RunEvent from = RunEvent::Start;
  RunEvent to = RunEvent::End;
};

// "FROM..TO" with two event names; std::invalid_argument naming the valid events otherwise.
RunSpan parse_span(std::string_view text);
std::string span_name(const RunSpan& span);

class RunEventRecorder : public motion::PlanObserver {
 public:
  // `main_program_file`: the main program's path as the loader was given it (the file name its
  // blocks carry).
  explicit RunEventRecorder(std::string main_program_file);
  void on_block(const motion::BlockTiming& timing) override;

  std::optional<double> time_of(RunEvent event) const;
  // to - from; none when either event has no time.
  std::optional<double> span_s(const RunSpan& span) const;

 private:
  std::string main_file_;
  // The file of the last block and whether it is a called program's: compared by name only when
  // the file changes (held, so that its address is not taken by another file's name meanwhile).
  FileName last_file_ = nullptr;
  bool last_in_call_ = false;
  double clock_s_ = 0;
  bool m0_seen_ = false;
  bool contour_over_ = false;
  std::optional<double> after_m0_, first_dwell_, dwell_after_m0_, contour_start_, contour_end_;
};

}  // namespace drycut::report
