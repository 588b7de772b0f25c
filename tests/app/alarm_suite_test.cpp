// Alarm regression suite: every tests/alarms/<case>.mpf is a bad program whose first line says
// `; expect <alarm number> <line> [extra drycut check arguments]`. Running `drycut check` on it
// must exit 1 and print that alarm at that line. Cases too big to commit are generated here.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
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

CliRun run_check(const fs::path& program, const std::string& extra_args) {
  return drycut::testing::run_in_folder("check", program, extra_args);
}

void expect_alarm(const fs::path& program, const Expectation& e) {
  const CliRun r = run_check(program, e.extra_args);
  SCOPED_TRACE(program.filename().string() + "\n" + r.out.substr(0, 2000));
  EXPECT_EQ(r.exit_code, 1);
  int number = 0, line = 0;
  ASSERT_TRUE(first_alarm(r.out, number, line));
  EXPECT_EQ(number, e.number);
  EXPECT_EQ(line, e.line);
}

fs::path temp_dir() {
  fs::path d = fs::temp_directory_path() / ("drycut_alarm_suite_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d;
}

TEST(AlarmSuite, EveryCommittedCaseRaisesItsAlarmAtItsLine) {
  const fs::path dir = fs::path(DRYCUT_TEST_DIR) / "alarms";
  std::vector<fs::path> cases;
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.path().extension() == ".mpf") cases.push_back(entry.path());
  std::sort(cases.begin(), cases.end());
  ASSERT_GE(cases.size(), 30u);
  std::vector<int> distinct_numbers;
  for (const auto& c : cases) {
    Expectation e;
    ASSERT_TRUE(read_expectation(c, e)) << c << ": first line must be '; expect <number> <line>'";
    expect_alarm(c, e);
    distinct_numbers.push_back(e.number);
  }
  std::sort(distinct_numbers.begin(), distinct_numbers.end());
  distinct_numbers.erase(std::unique(distinct_numbers.begin(), distinct_numbers.end()), distinct_numbers.end());
  EXPECT_GE(distinct_numbers.size(), 15u);  // the suite covers many alarm kinds, not one
}

TEST(AlarmSuite, TenMegabyteLineIsAnAlarmNotACrash) {
  const fs::path d = temp_dir();
  const fs::path p = d / "huge_line.mpf";
  {
    std::ofstream out(p, std::ios::binary);
    out << "G1 X1 F100\n";
    out << "G1 X";
    const std::string chunk(1 << 20, '1');
    for (int i = 0; i < 10; ++i) out << chunk;
    out << "\nM30\n";
  }
  expect_alarm(p, Expectation{12080, 2, ""});
  fs::remove_all(d);
}

TEST(AlarmSuite, EmptyFileIsAnAlarm) {
  const fs::path d = temp_dir();
  const fs::path p = d / "empty.mpf";
  std::ofstream(p, std::ios::binary).flush();
  expect_alarm(p, Expectation{990010, 1, ""});
  fs::remove_all(d);
}

TEST(AlarmSuite, DeeplyNestedParenthesesAreAnAlarmNotAStackOverflow) {
  const fs::path d = temp_dir();
  const fs::path p = d / "parens.mpf";
  {
    std::ofstream out(p, std::ios::binary);
    out << "X=" << std::string(50000, '(') << "1" << std::string(50000, ')') << "\nM30\n";
  }
  expect_alarm(p, Expectation{12080, 1, ""});
  fs::remove_all(d);
}

TEST(AlarmSuite, RandomBytesNeverCrash) {
  // Seeded garbage: the only acceptable outcomes are exit 0 or an alarm with exit 1.
  const fs::path d = temp_dir();
  uint32_t state = 12345;
  for (int round = 0; round < 20; ++round) {
    const fs::path p = d / ("garbage" + std::to_string(round) + ".mpf");
    {
      std::ofstream out(p, std::ios::binary);
      for (int i = 0; i < 4000; ++i) {
        state = state * 1664525u + 1013904223u;
        out.put(static_cast<char>(state >> 24));
      }
    }
    const CliRun r = run_check(p, "--max-steps 100000");
    EXPECT_TRUE(r.exit_code == 0 || r.exit_code == 1) << p << " exit " << r.exit_code << "\n" << r.out;
  }
  fs::remove_all(d);
}

}  // namespace
