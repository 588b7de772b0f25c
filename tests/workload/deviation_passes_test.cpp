// The thesis's 3-D program splits into entry, three loops and exit; control points go on loop 2.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "machine/machine_profile.hpp"
#include "workload/deviation_passes.hpp"
#include "workload/thesis_programs.hpp"

namespace drycut::workload {
namespace {

namespace fs = std::filesystem;

TEST(DeviationPasses, ProgressiveProgramHasEntryThreeLoopsAndExit) {
  const fs::path dir = fs::temp_directory_path() / ("drycut_passes_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  for (const auto& p : thesis_programs()) {
    if (p.main.file_name != "EKVI_C_15.MPF") continue;
    std::ofstream(dir / p.main.file_name) << p.main.text;
    std::ofstream(dir / p.sub.file_name) << p.sub.text;
  }
  SampleOptions options;
  options.step_mm = 0.1;
  options.tool_centre = false;
  const auto sampled = sample_program(dir / "EKVI_C_15.MPF", machine::default_profile(), options);
  fs::remove_all(dir);
  ASSERT_FALSE(sampled.program_alarm);
  const ReferenceContour reference(polar_curve(thesis_radius));
  const ContourSplit split = split_contour(sampled, reference);
  ASSERT_EQ(split.passes.size(), 5u);
  EXPECT_EQ(split.passes[0].name, "entry");
  EXPECT_EQ(split.passes[1].name, "loop 1");
  EXPECT_EQ(split.passes[3].name, "loop 3");
  EXPECT_EQ(split.passes[4].name, "exit");
  EXPECT_EQ(split.bottom_loop, 2u);
  EXPECT_NEAR(split.passes[2].mean_z_mm, -6.0, 1e-3);  // the spline overshoots Z a little at the seams
  EXPECT_NEAR(split.passes[1].mean_z_mm, -3.0, 0.05);  // Z falls linearly over loop 1
  EXPECT_DOUBLE_EQ(split.tool_radius_mm, 2.0);
}

}  // namespace
}  // namespace drycut::workload
