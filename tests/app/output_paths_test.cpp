// Output files never cost the user data and never end a failed write as a success: an output
// path naming the program is refused before anything is opened (the program stays as it was), a
// bad second output path leaves an earlier report untouched, and a write that fails (/dev/full:
// the disk is full) is exit code 2 with "error writing", for run, path and report alike.
#include <gtest/gtest.h>

#include <filesystem>

#include "report_cli_support.hpp"

namespace {

using namespace drycut::report_cli;

constexpr const char* kProgram = "G1 X10 F1000\nM30\n";

// The run's exit code and its standard error.
struct Outcome {
  int exit_code;
  std::string err;
};
Outcome run_with_stderr(const TempDir& dir, const std::string& args) {
  const auto err = dir.path / "stderr.txt";
  const CliRun r = run_drycut(args, err.string());
  return {r.exit_code, read_file(err)};
}

TEST(OutputPaths, AnOutputNamingTheProgramIsRefusedAndTheProgramKept) {
  TempDir dir("drycut_output_self");
  const auto program = dir.path / "P.MPF";
  write_file(program, kProgram);
  for (const std::string args : {"run -q --json", "run -q --ndjson", "run -q --trace", "report -o"}) {
    const Outcome r = run_with_stderr(dir, args + " " + quoted(program) + " " + quoted(program));
    EXPECT_EQ(r.exit_code, 2) << args << r.err;
    EXPECT_NE(r.err.find("it is the program to be read"), std::string::npos) << args << r.err;
    EXPECT_EQ(read_file(program), kProgram) << args;
  }
  const Outcome path = run_with_stderr(dir, "path " + quoted(program) + " --csv " + quoted(program));
  EXPECT_EQ(path.exit_code, 2) << path.err;
  EXPECT_EQ(read_file(program), kProgram);
}

TEST(OutputPaths, ABadSecondOutputLeavesTheFirstFileAsItWas) {
  TempDir dir("drycut_output_second");
  const auto program = dir.path / "P.MPF";
  write_file(program, kProgram);
  const auto earlier = dir.path / "earlier.json";
  write_file(earlier, "{\"kept\": true}\n");
  const Outcome r = run_with_stderr(dir, "run -q --json " + quoted(earlier) + " --trace " +
                                              quoted(dir.path / "no_dir" / "t.csv") + " " + quoted(program));
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(read_file(earlier), "{\"kept\": true}\n");
}

TEST(OutputPaths, AFailedWriteIsAnErrorNotASuccess) {
  if (!std::filesystem::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  TempDir dir("drycut_output_full");
  const auto program = dir.path / "P.MPF";
  write_file(program, kProgram);
  for (const std::string args : {"run -q --json /dev/full", "run -q --trace /dev/full", "path --csv /dev/full"}) {
    const Outcome r = run_with_stderr(dir, args + " " + quoted(program) + " >/dev/null");
    EXPECT_EQ(r.exit_code, 2) << args;
    EXPECT_NE(r.err.find("error writing /dev/full"), std::string::npos) << args << r.err;
  }
  const Outcome stdout_full = run_with_stderr(dir, "run -q " + quoted(program) + " >/dev/full");
  EXPECT_EQ(stdout_full.exit_code, 2);
  EXPECT_NE(stdout_full.err.find("error writing standard output"), std::string::npos) << stdout_full.err;
}

}  // namespace
