#pragma once
// MEASUREMENTS.json: measured times (and, where read, lowest feeds) of programs run on one
// machine, the input of `drycut calibrate` (format: docs/calibrate.md).
//
//   { "span": "after_dwell..contour_end",                  optional, default "start..end"
//     "min_feed_window": { "file_suffix": ".SPF",           optional, see below
//                          "between": "X22.000 Y0.000" },
//     "runs": [ { "program": "EKVI_LIN_90.MPF",             main program, relative to this file
//                 "time": 30.42,                            measured span in s
//                 "min_feed": 650,                          optional, lowest feed shown, mm/min
//                 "span": "after_m0..end" },                optional, overrides the default
//               ... ] }
//
// Other keys (descriptions, the knot count ...) are kept for the reader and ignored.
// The lowest feed is taken over the motion blocks (not G0) inside the run's span, leaving out
// blocks that start or end at rest (a standstill is not a feed shown while cutting); with
// min_feed_window only over blocks from files whose name ends with file_suffix, from the first
// block whose text contains `between` to the last one that does (the experiment's three loops
// from seam to seam: entry and exit knots left out).
#include <optional>
#include <string>
#include <vector>

#include "report/run_events.hpp"

namespace drycut::calibrate {

struct MeasuredRun {
  std::string name;      // the program's file name, for reports
  std::string program;   // path of the main program (resolved against the JSON's folder)
  report::RunSpan span;
  double time_s = 0;
  std::optional<double> min_feed_mm_min;
};

struct FeedWindow {
  std::string file_suffix;  // empty: every file
  std::string between;      // empty: the whole span
};

struct Measurements {
  std::vector<MeasuredRun> runs;
  std::optional<FeedWindow> feed_window;
};

class MeasurementsError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Reads and checks the file (MeasurementsError naming the file and the key on any fault).
Measurements load_measurements(const std::string& path);

}  // namespace drycut::calibrate
