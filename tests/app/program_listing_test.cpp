// Runs every tests/programs/<case>/MAIN.MPF through `drycut path --elements` and compares the
// element listing with the hand-reviewed expected.txt (lines starting with '#' are comments).
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace {

std::string run(const std::string& command) {
  std::string out;
  std::FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return out;
  std::array<char, 4096> buf{};
  while (size_t n = std::fread(buf.data(), 1, buf.size(), pipe)) out.append(buf.data(), n);
  pclose(pipe);
  return out;
}

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
    const std::string actual = run(std::string(DRYCUT_BINARY) + " path '" + main.string() + "' --elements");
    EXPECT_EQ(actual, expected_listing(entry.path() / "expected.txt")) << entry.path().filename();
  }
  EXPECT_GE(cases, 5);
}

}  // namespace
