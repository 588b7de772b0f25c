#pragma once
// The JSON report of `drycut run`, written while the plan streams: per-block rows go to the file
// as they are committed (a ten-million-block program never holds its rows in memory), the
// summary, dips and alarms are appended when the run ends.
//   { "program": ..., "machine": ..., "blocks": [ {file,line,label,time_s,length_mm,
//     v_max_mm_min,v_min_mm_min,limit,rapid}, ... ], "summary": {...}, "dips": [...],
//     "alarms": [...], "warnings": [...] }
// The summary also says whether the run went to the end (`complete`, `stopped_at` {file, line,
// alarm} or null) and where the last planned motion ended (`end_position_mm` {x, y, z}, machine
// coordinates, or null without motion), and, given the run's events, `events` {start, after_m0,
// after_dwell, contour_start, contour_end, end: seconds or null}, `span` ("FROM..TO" or null) and
// `span_s` (report/run_events.hpp).
#include <cstdio>
#include <optional>
#include <string>

#include "machine/alarm.hpp"
#include "motion/plan_result.hpp"
#include "report/run_completion.hpp"
#include "report/run_events.hpp"

namespace drycut::report {

class RunReportWriter : public motion::PlanObserver {
 public:
  // `out` stays owned by the caller.
  RunReportWriter(std::FILE* out, const std::string& program, const std::string& machine);
  void on_block(const motion::BlockTiming& timing) override;
  // Closes the document.
  void finish(const motion::PlanSummary& summary, const Diagnostics& diagnostics, const RunCompletion& completion,
              const std::optional<motion::Vec3>& end_position_mm, const RunEventRecorder* events = nullptr,
              const std::optional<RunSpan>& span = std::nullopt);

 private:
  std::FILE* out_;
  bool first_row_ = true;
};

// The summary object shared by the report and `--json` on stdout.
std::string summary_json(const motion::PlanSummary& summary, int indent = -1);
std::string alarm_json(const Alarm& alarm);

}  // namespace drycut::report
