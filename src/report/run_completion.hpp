#pragma once
// Whether a run went to the end of the program or was stopped by an alarm, and where. The control
// stops at the first alarm, so every figure of a stopped run (time, path length, feeds, dips)
// covers only the blocks before that alarm; every report that prints figures says so.
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "machine/alarm.hpp"

namespace drycut::report {

struct RunCompletion {
  bool complete = true;
  int alarm_number = 0;  // the alarm that stopped the run (0 when complete)
  std::string file;      // where it stopped: the file and line of that alarm
  uint32_t line = 0;
};

// The first alarm (not warning) in `diagnostics` is where the run stopped; `ended_in_alarm`
// marks a stopped run even when the alarm is not in the list.
RunCompletion run_completion(const std::vector<Alarm>& diagnostics, bool ended_in_alarm);

// "stopped by alarm 14040 at PART.MPF:9; the figures cover the blocks before it" (file name
// without folders), for text summaries and tables.
std::string incomplete_note(const RunCompletion& completion);

// A stopped run's CSV or listing (run --trace, path, path --elements) ends with one line
// "# INCOMPLETE: <incomplete_note>" so a file read later says it covers only part of the program
// (CSV readers skip it as a comment: pandas comment='#', gnuplot). Nothing for a complete run.
void mark_incomplete(std::FILE* out, const RunCompletion& completion);

// The standard cycles the run called that drycut does not simulate (warning 62900 "... not
// simulated, no time counted": turning, contour and measuring cycles), by name, each once: the
// run's time leaves them out, which a summary must say next to the time.
std::vector<std::string> untimed_cycles(const std::vector<Alarm>& diagnostics);

}  // namespace drycut::report
