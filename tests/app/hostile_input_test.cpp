// Hostile input through `drycut run` (loader -> interpreter -> compensation -> planner): every
// outcome is a clean run or an alarm, never a crash, a hang or an absurd time.
//   tests/alarms/run/<case>.mpf  first line `; expect <alarm> <line>`: `drycut run` must end in
//                                that alarm at that line (alarms only the interpreter or the
//                                planner can raise, so `drycut check` would not see them).
//   tests/alarms/ok/<case>.mpf   first line `; ok: <why>`: `drycut check` and `drycut run` must
//                                both exit 0 without an alarm, with a finite time.
//   tests/alarms/<case>.mpf      (the check suite) must also end in an alarm under `drycut run`.
// Big files are generated into a temporary folder, never committed.
#include <gtest/gtest.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "cli_support.hpp"

namespace {

namespace fs = std::filesystem;
using drycut::testing::CliRun;
using drycut::testing::Expectation;
using drycut::testing::first_alarm;
using drycut::testing::read_expectation;

CliRun run(const fs::path& program, const std::string& extra_args = "") {
  return drycut::testing::run_in_folder("run -q", program, extra_args);
}

// The summary's "time  <seconds> s" line; NaN when missing.
double summary_time(const std::string& output) {
  static const std::regex re(R"(\n\s*time\s+(\S+) s\n)");
  std::smatch m;
  if (!std::regex_search(output, m, re)) return std::nan("");
  try {
    return std::stod(m[1]);
  } catch (const std::exception&) {
    return std::nan("");
  }
}

// Nothing a program can say takes longer than this (a year): beyond it the time is absurd.
constexpr double kAbsurdTimeS = 365.0 * 24 * 3600;

void expect_alarm(const CliRun& r, int number, int line) {
  EXPECT_EQ(r.exit_code, 1);
  int got_number = 0, got_line = 0;
  ASSERT_TRUE(first_alarm(r.out, got_number, got_line));
  EXPECT_EQ(got_number, number);
  EXPECT_EQ(got_line, line);
  const double t = summary_time(r.out);
  EXPECT_TRUE(std::isfinite(t) && t >= 0 && t < kAbsurdTimeS) << "time " << t;
}

void expect_clean(const CliRun& r) {
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.out.find("ALARM"), std::string::npos);
  const double t = summary_time(r.out);
  EXPECT_TRUE(std::isfinite(t) && t >= 0 && t < kAbsurdTimeS) << "time " << t;
}

std::vector<fs::path> programs_in(const fs::path& dir) {
  std::vector<fs::path> v;
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.path().extension() == ".mpf") v.push_back(entry.path());
  std::sort(v.begin(), v.end());
  return v;
}

class TempDir {
 public:
  TempDir() : path_(fs::temp_directory_path() / ("drycut_hostile_" + std::to_string(::getpid()))) {
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

const fs::path kAlarmDir = fs::path(DRYCUT_TEST_DIR) / "alarms";

TEST(HostileInput, RunCasesEndInTheirAlarmAtTheirLine) {
  const auto cases = programs_in(kAlarmDir / "run");
  ASSERT_GE(cases.size(), 10u);
  for (const auto& c : cases) {
    Expectation e;
    ASSERT_TRUE(read_expectation(c, e)) << c << ": first line must be '; expect <number> <line>'";
    const CliRun r = run(c, e.extra_args);
    SCOPED_TRACE(c.filename().string() + "\n" + r.out.substr(0, 2000));
    expect_alarm(r, e.number, e.line);
  }
}

TEST(HostileInput, OkCasesRunCleanWithAFiniteTime) {
  const auto cases = programs_in(kAlarmDir / "ok");
  ASSERT_GE(cases.size(), 4u);
  for (const auto& c : cases) {
    std::ifstream in(c, std::ios::binary);
    std::string first;
    std::getline(in, first);
    EXPECT_EQ(first.rfind("; ok:", 0), 0u) << c << ": first line must be '; ok: <why>'";
    const CliRun checked = drycut::testing::run_in_folder("check", c, "");
    EXPECT_EQ(checked.exit_code, 0) << c << "\n" << checked.out;
    const CliRun r = run(c);
    SCOPED_TRACE(c.filename().string() + "\n" + r.out.substr(0, 2000));
    expect_clean(r);
  }
}

TEST(HostileInput, EveryCheckSuiteCaseAlsoEndsInAnAlarmUnderRun) {
  // The run stops at the first alarm: the loader's, or one the interpreter raises on an earlier
  // block (e.g. a G1 without F before the loader's syntax error). Never later, never none.
  for (const auto& c : programs_in(kAlarmDir)) {
    Expectation e;
    ASSERT_TRUE(read_expectation(c, e)) << c;
    const CliRun r = run(c, e.extra_args);
    SCOPED_TRACE(c.filename().string() + "\n" + r.out.substr(0, 2000));
    EXPECT_EQ(r.exit_code, 1);
    int number = 0, line = 0;
    ASSERT_TRUE(first_alarm(r.out, number, line));
    EXPECT_LE(line, e.line);
    if (line == e.line) {
      EXPECT_EQ(number, e.number);
    }
    const double t = summary_time(r.out);
    EXPECT_TRUE(std::isfinite(t) && t >= 0 && t < kAbsurdTimeS) << "time " << t;
  }
}

TEST(HostileInput, ProgramCallingItselfEndsInTheNestingAlarm) {
  TempDir d;
  const fs::path p = d.path() / "SELF.MPF";
  std::ofstream(p, std::ios::binary) << "G1 X1 F100\nSELF\nM30\n";
  const CliRun r = run(p);
  SCOPED_TRACE(r.out.substr(0, 2000));
  expect_alarm(r, 990003, 2);
}

TEST(HostileInput, HundredMegabyteProgramStreamsInBoundedMemory) {
  // 100 MB: short G1 moves, each with a long comment, so the file is big but the run quick.
  TempDir d;
  const fs::path p = d.path() / "big.mpf";
  const size_t kTargetBytes = 100u << 20;
  size_t blocks = 0;
  {
    std::ofstream out(p, std::ios::binary);
    out << "G1 X0 Y0 F3000\n";
    const std::string comment = " ; " + std::string(200, 'c') + "\n";
    size_t written = 0;
    char move[64];
    while (written < kTargetBytes) {
      const int n = std::snprintf(move, sizeof move, "X%.3f Y%.3f", (blocks % 1000) * 0.1, (blocks % 777) * 0.1);
      out.write(move, n);
      out << comment;
      written += static_cast<size_t>(n) + comment.size();
      ++blocks;
    }
    out << "M30\n";
  }
  ASSERT_GE(fs::file_size(p), kTargetBytes);
  const CliRun r = run(p);
  SCOPED_TRACE(r.out.substr(0, 2000));
  expect_clean(r);
#if !defined(__SANITIZE_ADDRESS__)
  // Peak RSS of the largest child so far (this one: the file is 100 MB, the others tiny).
  // Sanitizer builds are excluded: their shadow memory is not the program's.
  rusage usage{};
  getrusage(RUSAGE_CHILDREN, &usage);
  EXPECT_LT(usage.ru_maxrss, 100 * 1024) << "peak RSS " << usage.ru_maxrss << " KiB";
#endif
}

TEST(HostileInput, MegabyteCommentLineIsTheBlockLengthAlarm) {
  TempDir d;
  const fs::path p = d.path() / "long_line.mpf";
  std::ofstream(p, std::ios::binary) << "G1 X1 F100\nG1 X2 ;" << std::string(1 << 20, 'a') << "\nM30\n";
  const CliRun r = run(p);
  SCOPED_TRACE(r.out.substr(0, 2000));
  expect_alarm(r, 12080, 2);
}

TEST(HostileInput, DeepExpressionsAreSyntaxAlarmsNotStackOverflows) {
  TempDir d;
  struct Case {
    std::string name, text;
  };
  const std::vector<Case> cases{
      {"unary", "R1=" + std::string(20000, '-') + "1"},
      {"functions", "R1=" + [] {
         std::string s;
         for (int i = 0; i < 10000; ++i) s += "SIN(";
         return s + "1" + std::string(10000, ')');
       }()},
      {"parentheses", "X=" + std::string(30000, '(') + "1" + std::string(30000, ')')},
      {"not", "R1=" + [] {
         std::string s;
         for (int i = 0; i < 15000; ++i) s += "NOT ";
         return s + "1";
       }()},
  };
  for (const auto& c : cases) {
    const fs::path p = d.path() / (c.name + ".mpf");
    std::ofstream(p, std::ios::binary) << "G1 X1 F100\n" << c.text << "\nM30\n";
    const CliRun r = run(p);
    SCOPED_TRACE(c.name + "\n" + r.out.substr(0, 2000));
    expect_alarm(r, 12080, 2);
  }
}

TEST(HostileInput, LongButShallowExpressionEvaluates) {
  // 10000 terms in one sum: long, not deep; the loader must evaluate it (= 10000 * 0.001).
  TempDir d;
  const fs::path p = d.path() / "sum.mpf";
  std::string sum = "R1=0.001";
  for (int i = 1; i < 10000; ++i) sum += "+0.001";
  std::ofstream(p, std::ios::binary) << sum << "\nG1 X=R1 F600\nM30\n";
  const CliRun r = run(p);
  SCOPED_TRACE(r.out.substr(0, 2000));
  expect_clean(r);
  // 10 mm at 600 mm/min is at least 1 s (ramps add a little).
  EXPECT_GE(summary_time(r.out), 1.0);
  EXPECT_LT(summary_time(r.out), 2.0);
}

TEST(HostileInput, NonPrintableBytesAreBlanks) {
  // Fundamentals, "Character set": non-printable special characters are treated like blanks:
  // NUL bytes inside a block, a stray CR (CR CR LF after two conversions), DC2/DC4 tape codes, a
  // form feed, DEL. The blocks run as if those were blanks.
  TempDir d;
  const fs::path p = d.path() / "nul.mpf";
  std::ofstream(p, std::ios::binary) << "\x12G1 X1 F100\r\r\nG1 X2" << std::string(3, '\0') << "Y2\f\x7F\nM30\x14\n";
  const CliRun r = run(p);
  SCOPED_TRACE(r.out.substr(0, 2000));
  expect_clean(r);
}

}  // namespace
