#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>

#include "workload/thesis_programs.hpp"

namespace drycut::workload {
namespace {

size_t count_lines_with(const std::string& text, const std::string& needle) {
  std::istringstream in(text);
  size_t n = 0;
  for (std::string line; std::getline(in, line);)
    if (line.find(needle) != std::string::npos) ++n;
  return n;
}

size_t count_blocks(const std::string& text) {
  std::istringstream in(text);
  size_t n = 0;
  for (std::string line; std::getline(in, line);)
    if (!line.empty() && line[0] == 'N') ++n;
  return n;
}

const ThesisProgram& find(const std::vector<ThesisProgram>& all, const std::string& main_file) {
  auto it = std::find_if(all.begin(), all.end(), [&](const auto& p) { return p.main.file_name == main_file; });
  EXPECT_NE(it, all.end()) << main_file;
  return *it;
}

TEST(ThesisPrograms, TwentyFourProgressiveAndTwentyFourTwoDimensional) {
  const auto all = thesis_programs();
  EXPECT_EQ(all.size(), 48u);
  EXPECT_EQ(std::count_if(all.begin(), all.end(), [](const auto& p) { return p.mode == MillingMode::Progressive3D; }), 24);
}

TEST(ThesisPrograms, MainProgramFollowsTheExperimentsListing) {
  const auto all = thesis_programs();
  const auto& a = find(all, "EKVI_A_45.MPF");
  EXPECT_NE(a.main.text.find("N10 G54\n"), std::string::npos);
  EXPECT_NE(a.main.text.find("N20 T=\"FR_4\"\n"), std::string::npos);
  EXPECT_NE(a.main.text.find("N80 M0\n"), std::string::npos);
  EXPECT_NE(a.main.text.find("N120 BTAN ETAN\nN130 ASPLINE\nN140 X13.856 Y-8.000 Z0.500\nN150 EKVI_POSTUPNE_45\n"),
            std::string::npos)
      << a.main.text;
  const auto& b = find(all, "EKVI_B_45.MPF");
  EXPECT_EQ(b.main.text.find("BTAN"), std::string::npos);
  EXPECT_NE(b.main.text.find("X13.856 Y-8.000 Z0.500 PW=3"), std::string::npos);
  const auto& lin = find(all, "EKVI_LIN_45.MPF");
  EXPECT_NE(lin.main.text.find("G1 X37 Y-15\nN120 G1 X13.856 Y-8.000 Z0.500\n"), std::string::npos) << lin.main.text;
  const auto& c = find(all, "EKVI_C_45.MPF");
  EXPECT_NE(c.main.text.find("G1 X40\nN120 G1 X37\n"), std::string::npos) << c.main.text;
}

TEST(ThesisPrograms, SubprogramHasEntryThreeLoopsAndExit) {
  const auto all = thesis_programs();
  const auto& p = find(all, "POLAR_A_15.MPF");  // 24 knots, one every 15°
  // Entry knots at -15° (one, -30° is in the main program), seam, 3 × 24 loop knots, exit at 15° and 30°.
  EXPECT_EQ(count_blocks(p.sub.text), 1u + 1u + 72u + 2u);
  EXPECT_EQ(count_lines_with(p.sub.text, "Z-6.000"), 24u + 1u);  // loop 2 and the end of loop 1
  EXPECT_NE(p.sub.text.find("N2 X22.000 Y0.000 Z0.000\n"), std::string::npos) << p.sub.text;
  EXPECT_NE(p.sub.text.rfind("M17"), std::string::npos);
  const auto& lin = find(all, "POLAR_LIN_15.MPF");
  EXPECT_EQ(count_lines_with(lin.sub.text, " G1 "), count_blocks(lin.sub.text));
  const auto& b = find(all, "POLAR_B_15.MPF");
  EXPECT_EQ(count_lines_with(b.sub.text, "PW=3"), count_blocks(b.sub.text));
}

TEST(ThesisPrograms, TwoDimensionalLoopHasOverlapKnots) {
  const auto all = thesis_programs();
  const auto& p = find(all, "EKVI_A_15_2D.MPF");  // 56 distinct knots, overlap 2
  EXPECT_EQ(count_blocks(p.sub.text), 2u + 56u + 1u + 2u);
  EXPECT_NE(p.main.text.find("G1 Z-2 F2000"), std::string::npos);
}

}  // namespace
}  // namespace drycut::workload
