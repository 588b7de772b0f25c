#pragma once
// A one-line progress display for long runs: blocks executed, wall time, rate and (when known)
// simulated machine time, redrawn in place. It appears only after the run has taken a second,
// and only on a terminal: piped or redirected output stays clean.
#include <cstdint>
#include <cstdio>
#include <functional>
#include <string>

namespace drycut::report {

class ProgressDisplay {
 public:
  using Clock = std::function<double()>;  // monotonic seconds

  ProgressDisplay(std::FILE* out, bool enabled, Clock clock = steady_seconds);
  // Enabled when not quiet and standard error is a terminal (isatty(2)).
  static ProgressDisplay for_stderr(bool quiet);
  ~ProgressDisplay();
  ProgressDisplay(const ProgressDisplay&) = delete;
  ProgressDisplay& operator=(const ProgressDisplay&) = delete;
  ProgressDisplay(ProgressDisplay&&) = delete;  // for_stderr returns a prvalue: elided

  // Cheap to call every block: the clock is read only every `kCallsPerCheck` calls.
  void update(uint64_t blocks, double simulated_s = -1.0);
  // Draws `text` in place of the block count, with the same delay and redraw interval (for
  // callers that count something else, e.g. programs done). Call it a few times a second.
  void show(const std::string& text);
  // Clears the line if one was drawn (also done by the destructor).
  void finish();

  bool enabled() const { return enabled_; }
  bool shown() const { return shown_; }

  static double steady_seconds();
  static constexpr double kDelay_s = 1.0;     // nothing for runs shorter than this
  static constexpr double kInterval_s = 0.2;  // redraw at most this often
  static constexpr uint32_t kCallsPerCheck = 256;

 private:
  std::FILE* out_;
  bool enabled_;
  Clock clock_;
  double start_ = 0, last_draw_ = 0;
  uint32_t calls_ = 0;
  bool shown_ = false;
};

}  // namespace drycut::report
