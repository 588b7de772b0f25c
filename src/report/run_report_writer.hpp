#pragma once
// The JSON report of `drycut run`, written while the plan streams: per-block rows go out as they
// are committed (a ten-million-block program never holds its rows in memory), the file table,
// summary, dips and alarms when the run ends. Two layouts (schemas in docs/schemas/):
//
// Document (`--json FILE|-`, docs/schemas/run.schema.json): one JSON object
//   { "format": "drycut-run", "version": 2, "program", "machine",
//     "block_columns": ["file","line","label","time_s","length_mm","v_max_mm_min",
//                       "v_min_mm_min","limit","rapid"],
//     "blocks": [ [0, 4, "M6 FR_4", 4, 0, 0, 0, "exact_stop", false], ... ],
//     "files": ["/abs/PART.MPF", "/abs/SUB.SPF"],   -- a row's "file" is an index into it
//     "summary": {...}, "dips": [...], "alarms": [...], "warnings": [...] }
//   Rows are arrays in the order of block_columns and carry the file as an index: a row of a
//   1 M-block program is about 60 bytes instead of about 210 with the path and keys repeated.
//   Rows give times to 0.1 µs, lengths to 1 nm, feeds to 0.001 mm/min (the summary's values are
//   the exact doubles).
//
// Lines (`--ndjson FILE|-`, docs/schemas/run-ndjson.schema.json): one JSON object per line,
// each with a "type": "run" (program, machine) first; "file" {id, path} before the first block
// of each file; "block" {file, line, label, time_s, length_mm, v_max_mm_min, v_min_mm_min,
// limit, rapid}; then "dip", "alarm", "warning" lines and "summary" last.
//
// The summary says whether the run went to the end (`complete`, `stopped_at` {file, line,
// alarm} or null) and where the last planned motion ended (`end_position_mm` {x, y, z},
// machine coordinates, or null without motion).
// Given the run's events, the summary also has `events` {start, after_m0, after_dwell,
// contour_start, contour_end, end: seconds or null}, `span` ("FROM..TO" or null) and `span_s`
// (report/run_events.hpp).
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "machine/alarm.hpp"
#include "motion/plan_result.hpp"
#include "report/run_completion.hpp"
#include "report/run_events.hpp"

namespace drycut::report {

enum class RunJsonLayout { Document, Lines };

class RunReportWriter : public motion::PlanObserver {
 public:
  // `out` stays owned by the caller.
  RunReportWriter(std::FILE* out, RunJsonLayout layout, const std::string& program, const std::string& machine);
  void on_block(const motion::BlockTiming& timing) override;
  // Closes the document (or ends the stream with the summary line) and flushes.
  void finish(const motion::PlanSummary& summary, const Diagnostics& diagnostics, const RunCompletion& completion,
              const std::optional<motion::Vec3>& end_position_mm, const RunEventRecorder* events = nullptr,
              const std::optional<RunSpan>& span = std::nullopt);

  static constexpr size_t kFlushBytes = 1 << 16;

 private:
  // The index of the row's file in the file table (a new file is added, and announced in Lines).
  size_t file_index(const BlockRef& source);
  const std::string& escaped_label(const std::string& label);
  void flush();

  std::FILE* out_;
  RunJsonLayout layout_;
  std::string buffer_;
  bool first_row_ = true;
  std::vector<std::string> files_;
  std::unordered_map<std::string, size_t> file_ids_;
  // The previous row's shared file name, held so that its address cannot be reused by another.
  FileName last_file_ = nullptr;
  size_t last_file_id_ = 0;
  std::unordered_map<std::string, std::string> labels_;  // label -> its JSON string
};

// The column names of a Document row, in order.
const std::vector<std::string>& block_columns();

// The summary object shared by the report and `--json` on stdout.
std::string summary_json(const motion::PlanSummary& summary, int indent = -1);
std::string alarm_json(const Alarm& alarm);

}  // namespace drycut::report
