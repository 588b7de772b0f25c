// Runs every tests/programs/<case>/MAIN.MPF through `drycut path --elements` and compares the
// element listing with the hand-reviewed expected.txt (lines starting with '#' are comments).
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "cli_support.hpp"

namespace {

std::string expected_listing(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::string line, out;
  while (std::getline(in, line))
    if (line.empty() || line[0] != '#') out += line + "\n";
  return out;
}

TEST(ProgramListings, EveryCaseMatchesItsReviewedListing) {
  const std::filesystem::path root = std::filesystem::path(DRYCUT_TEST_DIR) / "programs";
  int cases = 0;
  for (const auto& entry : std::filesystem::directory_iterator(root)) {
    if (!entry.is_directory()) continue;
    ++cases;
    const auto main = entry.path() / "MAIN.MPF";
    const std::string actual =
        drycut::testing::run_shell(drycut::testing::drycut_command("path '" + main.string() + "' --elements")).out;
    EXPECT_EQ(actual, expected_listing(entry.path() / "expected.txt")) << entry.path().filename();
  }
  EXPECT_GE(cases, 5);
}

}  // namespace
