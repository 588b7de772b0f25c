// The committed programs/thesis files are exactly what the generator writes now (no drift), and
// their first knots are the experiment's listing.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "workload/thesis_programs.hpp"

namespace drycut::workload {
namespace {

std::string read(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

const std::filesystem::path kDir = std::filesystem::path(DRYCUT_SOURCE_DIR) / "programs" / "thesis";

TEST(CommittedThesisPrograms, AreWhatTheGeneratorWritesNow) {
  size_t files = 0;
  for (const auto& p : thesis_programs()) {
    for (const ProgramFile* f : {&p.main, &p.sub}) {
      ASSERT_TRUE(std::filesystem::exists(kDir / f->file_name)) << f->file_name << ": run programs/thesis/generate.sh";
      EXPECT_EQ(read(kDir / f->file_name), f->text) << f->file_name << " drifted: run programs/thesis/generate.sh";
      ++files;
    }
  }
  EXPECT_EQ(files, 96u);
}

TEST(CommittedThesisPrograms, FirstKnotsMatchTheExperimentsListing) {
  // 5 degree polar set: the seam knot X22.000 Y0.000, then X21.330 Y1.866 (EXPERIMENT.md §2).
  const std::string sub = read(kDir / "POLAR_POSTUPNE_5.SPF");
  const size_t seam = sub.find("X22.000 Y0.000 Z0.000\n");
  ASSERT_NE(seam, std::string::npos);
  const size_t next = sub.find('\n', seam) + 1;
  EXPECT_EQ(sub.substr(next, sub.find(' ', next) - next).front(), 'N');
  EXPECT_NE(sub.substr(next, 40).find("X21.330 Y1.866"), std::string::npos);
}

}  // namespace
}  // namespace drycut::workload
