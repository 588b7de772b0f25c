// `--tools FILE`: the tool table of a run replaces the profile's (length and radius visible in
// the element listing), and a bad file is a usage error (exit code 2).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "cli_support.hpp"

namespace drycut::testing {
namespace {

namespace fs = std::filesystem;

fs::path fresh_folder(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("drycut_tools_" + std::to_string(::getpid()) + "_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

TEST(ToolsOption, CsvTableGivesLengthAndRadius) {
  const fs::path dir = fresh_folder("csv");
  std::ofstream(dir / "tools.csv") << "number,name,d,length_mm,radius_mm\n1,FR_4,1,75,3\n";
  std::ofstream(dir / "P.MPF") << "T1 D1\nM6\nG0 Z0\nG41 G1 X10 F600\nM30\n";
  // Z0 with a 75 mm tool: the carrier stops at Z75; G41 uses the file's radius 3.
  const CliRun r = run_in_folder("path --elements", dir / "P.MPF", "--tools tools.csv");
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("-> (0.000 0.000 75.000)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("G41 r=3.000"), std::string::npos) << r.out;
  fs::remove_all(dir);
}

TEST(ToolsOption, MissingOrMalformedFileIsAUsageError) {
  const fs::path dir = fresh_folder("bad");
  std::ofstream(dir / "P.MPF") << "T1 M6\nM30\n";
  std::ofstream(dir / "bad.csv") << "number,d,colour\n";
  EXPECT_EQ(run_in_folder("run -q", dir / "P.MPF", "--tools nope.csv").exit_code, 2);
  const CliRun bad = run_in_folder("run -q", dir / "P.MPF", "--tools bad.csv");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.out.find("unknown column 'colour'"), std::string::npos) << bad.out;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace drycut::testing
