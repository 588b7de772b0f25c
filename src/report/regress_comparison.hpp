#pragma once
// Comparing a `drycut regress` run with its baseline. Every difference beyond the tolerance is a
// change and fails the run, in either direction: the baseline records what the control does,
// and a program that got faster after a change of drycut is as suspect as one that got slower
// (`--update` accepts the new figures).
//   time, time after M0  |now - base| <= tolerance "time"   (default 2 % of the baseline)
//   lowest feed          |now - base| <= tolerance "feed"   (default 5 %)
//   path length          |now - base| <= tolerance "length" (default 0.1 %)
//   feed dips (count)    |now - base| <= tolerance "dips"   (default 0)
//   complete, error, alarms, warnings (number, file, line, count): must be equal
//   a program missing from the baseline, or in the baseline and not run: a change
#include <string>
#include <vector>

#include "report/regress_baseline.hpp"

namespace drycut::report {

// A tolerance is relative ("2%": of the baseline value) or absolute ("0.5": in the figure's unit).
struct Tolerance {
  double relative = 0;
  double absolute = 0;
  bool allows(double baseline, double now) const;
  std::string text() const;  // "2 %" or "0.5"
};

struct RegressTolerances {
  Tolerance time{0.02, 0};
  Tolerance feed{0.05, 0};
  Tolerance length{0.001, 0};
  Tolerance dips{0, 0};
};

// "time=2%,feed=5%,length=0.1%,dips=1": keys time, feed, length, dips; unnamed keys keep their
// defaults. Throws UsageError for an unknown key or a value that is not a non-negative number.
RegressTolerances parse_tolerances(const std::string& spec);

struct RegressChange {
  std::string program;
  std::string what;      // "time", "lowest feed", "alarm", "new program" ...
  std::string baseline;  // the value before ("-" when there was none)
  std::string now;       // the value now
  std::string note;      // "+6.5 %, tolerance 2 %"
  std::string message() const;  // "time 12.30 s -> 13.10 s (+6.5 %, tolerance 2 %)"
};

// The changes of `now` (sorted by program) against `baseline`, by program then figure.
std::vector<RegressChange> compare_with_baseline(const Baseline& baseline, const std::vector<ProgramFigures>& now,
                                                 const RegressTolerances& tolerances);

// A plain-text table: program | what | baseline | now | note.
std::string change_table(const std::vector<RegressChange>& changes);

}  // namespace drycut::report
