// Conformance suite: every tests/conformance/<topic>/NAME.mpf is a small program for one rule of
// the control, whose header states the rule and the expected outcome (conformance_header.hpp).
// One test per program, found when the test binary starts (CTest lists test_app at test time,
// so a new program needs no rebuild) and named after its path: harness/arc_end.mpf ->
// Conformance/Program.harness_arc_end. In the program's folder each test runs
//   drycut check NAME --json           and   drycut run NAME -q --json FILE
// and checks that both agree with `expect:` (exit code, number and line of the first alarm),
// that `run` reports every `expect-warning:`, that the run's summary ends at `expect-end:`
// (summary.end_position_mm, tolerance 1e-4 mm) and takes `expect-time:`, that the summary's
// complete/stopped_at agree with the outcome, and with `expect-listing:` that
// `drycut path NAME --elements` prints the listing file (lines starting with '#' are comments);
// `expect-tool-centre:` the same for `drycut path NAME --tool-centre --elements`.
// With `profile:` every command gets `--machine FILE` (a machine profile beside the program).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "cli_support.hpp"
#include "conformance_header.hpp"

namespace {

namespace fs = std::filesystem;
using drycut::testing::CliRun;
using drycut::testing::ConformanceSpec;
using drycut::testing::run_shell;
using nlohmann::json;

constexpr double kEndTolerance_mm = 1e-4;

fs::path conformance_root() { return fs::path(DRYCUT_TEST_DIR) / "conformance"; }

bool is_main_program(const fs::path& p) {
  std::string ext = p.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext == ".mpf";
}

// Every main program under tests/conformance, as paths relative to it, sorted.
std::vector<std::string> find_programs() {
  std::vector<std::string> out;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(conformance_root(), ec), end; !ec && it != end; it.increment(ec))
    if (it->is_regular_file() && is_main_program(it->path()))
      out.push_back(fs::relative(it->path(), conformance_root()).generic_string());
  std::sort(out.begin(), out.end());
  return out;
}

const std::vector<std::string>& programs() {
  static const std::vector<std::string> list = find_programs();
  return list;
}

// "harness/arc-end.mpf" -> "harness_arc_end"; a name two paths share gets the index appended.
std::string sanitized(const std::string& relative) {
  std::string name = fs::path(relative).replace_extension().generic_string();
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

std::string test_name(const ::testing::TestParamInfo<std::string>& info) {
  // Counted once: every test process names all programs at start (CTest runs one per test), and
  // comparing each with all was quadratic (0.3 s per process, seconds under the sanitizers).
  static const std::map<std::string, int> uses = [] {
    std::map<std::string, int> m;
    for (const std::string& p : programs()) ++m[sanitized(p)];
    return m;
  }();
  const std::string name = sanitized(info.param);
  return uses.at(name) > 1 ? name + "_" + std::to_string(info.index) : name;
}

std::string quoted(const fs::path& p) { return "'" + p.string() + "'"; }

// "cd <folder> && drycut <command> 'NAME' <args>", run in the program's folder as the suite asks.
std::string in_folder(const fs::path& program, const std::string& command, const std::string& args) {
  return "cd " + quoted(program.parent_path()) + " && " +
         drycut::testing::drycut_command(command + " " + quoted(program.filename()) + " " + args);
}

// What one command said: its exit code, its first alarm and its warnings.
struct Outcome {
  int exit_code = -1;
  int alarm_number = 0;  // 0: no alarm
  int alarm_line = 0;
  std::vector<int> warnings;
};

Outcome outcome_of(int exit_code, const json& diagnostics_list) {
  Outcome o;
  o.exit_code = exit_code;
  for (const auto& a : diagnostics_list) {
    if (a.value("severity", "") == "warning") {
      o.warnings.push_back(a.value("number", 0));
    } else if (o.alarm_number == 0) {
      o.alarm_number = a.value("number", 0);
      o.alarm_line = a.value("line", 0);
    }
  }
  return o;
}

void expect_outcome(const char* command, const Outcome& o, const ConformanceSpec& spec) {
  SCOPED_TRACE(command);
  if (spec.expect_alarm) {
    EXPECT_EQ(o.exit_code, 1);
    EXPECT_EQ(o.alarm_number, spec.alarm_number);
    EXPECT_EQ(o.alarm_line, spec.alarm_line);
  } else {
    EXPECT_EQ(o.exit_code, 0);
    EXPECT_EQ(o.alarm_number, 0) << "unexpected alarm at line " << o.alarm_line;
  }
}

std::string expected_listing(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::string line, out;
  while (std::getline(in, line))
    if (line.empty() || line[0] != '#') out += line + "\n";
  return out;
}

void expect_end_position(const json& summary, const ConformanceSpec& spec) {
  const json& end = summary.contains("end_position_mm") ? summary["end_position_mm"] : json();
  ASSERT_TRUE(end.is_object()) << "expect-end given, but the run has no end position (no motion?)";
  static constexpr const char* kAxes[] = {"x", "y", "z"};
  for (int i = 0; i < 3; ++i) {
    if (spec.end_mm[i]) {
      EXPECT_NEAR(end.at(kAxes[i]).get<double>(), *spec.end_mm[i], kEndTolerance_mm) << "axis " << kAxes[i];
    }
  }
}

// The run's summary agrees with its outcome: complete exactly when no alarm stopped it.
void expect_completion(const json& summary, const ConformanceSpec& spec) {
  EXPECT_EQ(summary.value("complete", spec.expect_alarm), !spec.expect_alarm) << "summary.complete";
  if (spec.expect_alarm) {
    ASSERT_TRUE(summary.contains("stopped_at") && summary["stopped_at"].is_object()) << "summary.stopped_at";
    EXPECT_EQ(summary["stopped_at"].value("line", 0), spec.alarm_line) << "summary.stopped_at.line";
  }
}

// A temporary file removed however the test ends (an ASSERT returns early).
struct RemovedAtEnd {
  fs::path path;
  ~RemovedAtEnd() {
    std::error_code ec;
    fs::remove(path, ec);
  }
};

class Conformance : public ::testing::TestWithParam<std::string> {};

TEST_P(Conformance, Program) {
  const fs::path program = conformance_root() / GetParam();
  ConformanceSpec spec;
  std::string error;
  {
    std::ifstream in(program, std::ios::binary);
    ASSERT_TRUE(in) << "cannot read " << program;
    ASSERT_TRUE(drycut::testing::read_conformance_header(in, spec, error)) << GetParam() << ": " << error;
  }
  SCOPED_TRACE(GetParam() + "\nrule: " + spec.rule);

  // check: JSON on stdout (alarms and warnings in it), the stderr copy dropped.
  const std::string profile = spec.profile.empty() ? "" : "--machine " + quoted(fs::path(spec.profile)) + " ";
  const CliRun check = run_shell(in_folder(program, "check", profile + "--json 2>/dev/null"));
  json check_json;
  ASSERT_NO_THROW(check_json = json::parse(check.out)) << "check printed no JSON:\n" << check.out.substr(0, 2000);
  expect_outcome("drycut check", outcome_of(check.exit_code, check_json.value("alarms", json::array())), spec);

  // run: the JSON report into a file of this process, the text summary and stderr for the trace.
  const fs::path report = fs::temp_directory_path() / ("drycut_conformance_" + std::to_string(::getpid()) + "_" +
                                                       sanitized(GetParam()) + ".json");
  const RemovedAtEnd report_file{report};
  const CliRun run = run_shell(in_folder(program, "run", profile + "-q --json " + quoted(report) + " 2>&1"));
  SCOPED_TRACE("drycut run said:\n" + run.out.substr(0, 2000));
  json run_json;
  {
    std::ifstream in(report, std::ios::binary);
    ASSERT_NO_THROW(run_json = json::parse(in)) << "run wrote no JSON report";
  }
  json diagnostics = run_json.value("alarms", json::array());
  for (const auto& w : run_json.value("warnings", json::array())) diagnostics.push_back(w);
  const Outcome run_outcome = outcome_of(run.exit_code, diagnostics);
  expect_outcome("drycut run", run_outcome, spec);
  for (int w : spec.warnings) {
    const bool reported = std::count(run_outcome.warnings.begin(), run_outcome.warnings.end(), w) > 0;
    EXPECT_TRUE(reported) << "expected warning " << w << " not reported by run";
  }

  const json summary = run_json.value("summary", json::object());
  expect_completion(summary, spec);
  if (spec.has_end) expect_end_position(summary, spec);
  if (spec.time_s) {
    EXPECT_NEAR(summary.value("time_s", -1.0), *spec.time_s, spec.time_tolerance_s) << "summary.time_s";
  }

  auto expect_listing = [&](const std::string& file, const std::string& options) {
    if (file.empty()) return;
    const fs::path listing = program.parent_path() / file;
    ASSERT_TRUE(fs::exists(listing)) << "the header names a missing listing " << listing;
    const CliRun path = run_shell(in_folder(program, "path", profile + options + " 2>/dev/null"));
    EXPECT_EQ(path.out, expected_listing(listing)) << "drycut path " << options << " differs from " << file;
  };
  expect_listing(spec.listing, "--elements");
  expect_listing(spec.tool_centre_listing, "--tool-centre --elements");
}

INSTANTIATE_TEST_SUITE_P(Conformance, Conformance, ::testing::ValuesIn(programs()), test_name);

// The runner's own programs are there: an empty suite would pass without running anything.
TEST(ConformanceSuite, FindsTheHarnessPrograms) {
  const auto& all = programs();
  const auto harness = std::count_if(all.begin(), all.end(), [](const std::string& p) { return p.rfind("harness/", 0) == 0; });
  EXPECT_GE(harness, 3);
}

}  // namespace
