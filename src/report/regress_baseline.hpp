#pragma once
// The figures `drycut regress` keeps per program, and the baseline file that records them
// (docs/schemas/regress-baseline.schema.json, docs/regress.md). The file is meant to be
// committed: programs are keyed by their path relative to the baseline's folder ('/' separators),
// sorted; alarms and warnings name the file without folders; values are rounded (time 0.1 ms,
// length 0.1 µm, feed 0.001 mm/min) so that a rewrite without a real change leaves it as it was.
//   { "format": "drycut-regress-baseline", "version": 1, "machine": "...",
//     "programs": { "thesis/EKVI_A_15.MPF": { "time_s", "time_after_m0_s", "min_feed_mm_min",
//        "path_length_mm", "dips", "complete", "error",
//        "alarms": [ {number, file, line, count} ], "warnings": [ ... ] }, ... } }
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "machine/alarm.hpp"

namespace drycut::report {

// One alarm or warning, without its text: what a change in the control's semantics changes.
struct DiagnosticKey {
  int number = 0;
  std::string file;  // file name without folders
  uint32_t line = 0;
  size_t count = 1;  // how often it was raised there
  auto operator<=>(const DiagnosticKey&) const = default;
  std::string text() const;  // "10751 at EKVI_B_90.SPF:33" (" x3" when counted more than once)
};

struct ProgramFigures {
  std::string program;  // relative path with '/' (the baseline key)
  double time_s = 0;
  double time_after_m0_s = 0;
  double min_feed_mm_min = 0;
  double path_length_mm = 0;
  size_t dips = 0;
  bool complete = true;
  std::string error;  // the program could not be run at all (unreadable file ...); empty otherwise
  std::vector<DiagnosticKey> alarms, warnings;  // sorted
};

// Fills alarms and warnings from a run's diagnostics (grouped, counted, sorted).
void set_diagnostics(ProgramFigures& figures, const std::vector<Alarm>& diagnostics);

struct Baseline {
  std::string machine;
  std::vector<ProgramFigures> programs;  // sorted by program
};

std::string baseline_json(const Baseline& baseline);
// Throws UsageError naming what is wrong when `text` is not a baseline.
Baseline parse_baseline(const std::string& text);

}  // namespace drycut::report
