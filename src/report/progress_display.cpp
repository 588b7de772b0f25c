#include "report/progress_display.hpp"

#include <unistd.h>

#include <chrono>

namespace drycut::report {

double ProgressDisplay::steady_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

ProgressDisplay::ProgressDisplay(std::FILE* out, bool enabled, Clock clock)
    : out_(out), enabled_(enabled && out != nullptr), clock_(std::move(clock)) {
  if (enabled_) start_ = last_draw_ = clock_();
}

ProgressDisplay ProgressDisplay::for_stderr(bool quiet) { return ProgressDisplay(stderr, !quiet && ::isatty(2) == 1); }

ProgressDisplay::~ProgressDisplay() { finish(); }

void ProgressDisplay::update(uint64_t blocks, double simulated_s) {
  if (!enabled_ || ++calls_ < kCallsPerCheck) return;
  calls_ = 0;
  const double now = clock_();
  const double elapsed = now - start_;
  if (elapsed < kDelay_s || now - last_draw_ < kInterval_s) return;
  last_draw_ = now;
  shown_ = true;
  const double rate = elapsed > 0 ? static_cast<double>(blocks) / elapsed : 0.0;
  std::fprintf(out_, "\r  %llu blocks  %.1f s  %.0f blocks/s", static_cast<unsigned long long>(blocks), elapsed, rate);
  if (simulated_s >= 0) std::fprintf(out_, "  machine time %.1f s", simulated_s);
  std::fputs("\x1b[K", out_);  // erase what a longer previous line left
  std::fflush(out_);
}

void ProgressDisplay::show(const std::string& text) {
  if (!enabled_) return;
  const double now = clock_();
  if (now - start_ < kDelay_s || now - last_draw_ < kInterval_s) return;
  last_draw_ = now;
  shown_ = true;
  std::fprintf(out_, "\r%s\x1b[K", text.c_str());
  std::fflush(out_);
}

void ProgressDisplay::finish() {
  if (!shown_) return;
  std::fputs("\r\x1b[K", out_);
  std::fflush(out_);
  shown_ = false;
}

}  // namespace drycut::report
