#pragma once
// `drycut compare`: one row per program (the numbers of its run summary), as a terminal table,
// JSON and an HTML page with the programmed paths overlaid (id "compare-paths").
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "report/run_completion.hpp"
#include "report/svg_decimator.hpp"

namespace drycut::report {

struct CompareRow {
  std::string program;
  double time_s = 0;
  double time_after_m0_s = 0;
  double min_feed_mm_min = 0;
  size_t dips = 0;
  double path_length_mm = 0;
  uint64_t program_bytes = 0;  // main program and every subprogram it used
  bool has_deviation = false;
  double max_deviation_mm = 0;
  size_t alarms = 0;
  RunCompletion completion;     // a stopped run's figures cover only the blocks before its alarm
  std::vector<PlotPoint> path;  // programmed path (decimated), for the overlay
};

// Fixed-width text table, one line per program; a stopped run's line says INCOMPLETE and where.
std::string compare_table_text(const std::vector<CompareRow>& rows);
// {"programs": [{program, time_s, time_after_m0_s, min_feed_mm_min, dips, path_length_mm,
//   program_bytes, max_deviation_mm (null without reference), alarms, complete,
//   stopped_at ({file, line, alarm} or null)}, ...]}
std::string compare_json(const std::vector<CompareRow>& rows);
std::string render_compare_report(const std::vector<CompareRow>& rows,
                                  const std::vector<std::pair<double, double>>& reference,
                                  const std::string& reference_name);

// The colour of the i-th program in the overlay (distinct for the first ten, then repeating).
std::string program_colour(size_t index);

}  // namespace drycut::report
