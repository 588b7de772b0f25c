#include "report/progress_display.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <string>

namespace drycut::report {
namespace {

std::string contents(std::FILE* f) {
  std::fflush(f);
  std::rewind(f);
  std::string s;
  char buf[256];
  while (size_t n = std::fread(buf, 1, sizeof buf, f)) s.append(buf, n);
  return s;
}

// Drives the display with a fake clock that advances `step` seconds per reading.
struct FakeClock {
  double now = 100.0, step = 0.0;
  ProgressDisplay::Clock fn() {
    return [this] { return now += step; };
  }
};

TEST(ProgressDisplay, DisabledPrintsNothing) {
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  FakeClock clock{100.0, 1.0};
  {
    ProgressDisplay p(f, false, clock.fn());
    for (uint64_t i = 0; i < 100'000; ++i) p.update(i, 1.0);
  }
  EXPECT_EQ(contents(f), "");
  std::fclose(f);
}

TEST(ProgressDisplay, NothingWhenStderrIsNotATerminal) {
  // Point fd 2 at a file for the duration of the test, as `drycut run ... 2>log` does.
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  std::fflush(stderr);
  const int saved = ::dup(2);
  ASSERT_GE(saved, 0);
  ASSERT_GE(::dup2(::fileno(f), 2), 0);
  const bool enabled = ProgressDisplay::for_stderr(false).enabled();
  std::fflush(stderr);
  ::dup2(saved, 2);
  ::close(saved);
  EXPECT_FALSE(enabled);
  EXPECT_EQ(contents(f), "");
  std::fclose(f);
}

TEST(ProgressDisplay, QuietDisables) { EXPECT_FALSE(ProgressDisplay::for_stderr(true).enabled()); }

TEST(ProgressDisplay, ShortRunsShowNothing) {
  std::FILE* f = std::tmpfile();
  FakeClock clock{100.0, 0.0};
  {
    ProgressDisplay p(f, true, clock.fn());
    clock.step = 0.5 / 1000;  // 1000 clock readings = 0.5 s < the 1 s delay
    for (uint64_t i = 0; i < 1000 * ProgressDisplay::kCallsPerCheck; ++i) p.update(i);
    EXPECT_FALSE(p.shown());
  }
  EXPECT_EQ(contents(f), "");
  std::fclose(f);
}

TEST(ProgressDisplay, LongRunsShowBlocksRateAndMachineTime) {
  std::FILE* f = std::tmpfile();
  FakeClock clock{100.0, 0.0};
  std::string text;
  {
    ProgressDisplay p(f, true, clock.fn());
    clock.step = 2.0;  // every check is 2 s later
    for (uint64_t i = 1; i <= ProgressDisplay::kCallsPerCheck; ++i) p.update(i, 12.5);
    EXPECT_TRUE(p.shown());
    text = contents(f);
    p.finish();
    EXPECT_FALSE(p.shown());
  }
  // 256 blocks after 2 s of wall time: 128 blocks/s.
  EXPECT_NE(text.find("256 blocks"), std::string::npos) << text;
  EXPECT_NE(text.find("128 blocks/s"), std::string::npos) << text;
  EXPECT_NE(text.find("machine time 12.5 s"), std::string::npos) << text;
  EXPECT_EQ(text[0], '\r');
  std::fclose(f);
}

}  // namespace
}  // namespace drycut::report
