// The datum each profile key models, as `drycut profile show` prints it, and the flat rows of a
// profile's JSON.
#include <gtest/gtest.h>

#include "machine/machine_profile.hpp"
#include "machine/profile_md_names.hpp"

namespace drycut::machine {
namespace {

TEST(ProfileMdNames, KeysWithUnitsNameTheirDatum) {
  EXPECT_EQ(md_name_of("axes.X.max_velocity_mm_min"), "MD32000 MAX_AX_VELO");
  EXPECT_EQ(md_name_of("axes.C.max_velocity_deg_min"), "MD32000 MAX_AX_VELO");
  EXPECT_EQ(md_name_of("axes.X.max_accel_m_s2"), "MD32300 MAX_AX_ACCEL");
  EXPECT_EQ(md_name_of("path.max_accel_ovl_factor"), "MD32310 MAX_ACCEL_OVL_FACTOR");
  EXPECT_EQ(md_name_of("axes.Z.min_mm"), "MD36100 POS_LIMIT_MINUS");
  EXPECT_EQ(md_name_of("path.ipo_cycle_ms"), "MD10050 SYSCLOCK_CYCLE_TIME x MD10070 IPO_SYSCLOCK_TIME_RATIO");
  EXPECT_EQ(md_name_of("program.work_offsets_mm.G54"), "$P_UIFR (settable frames)");
  EXPECT_EQ(md_name_of("machine_data.$MA_COMPRESS_POS_TOL[X1]"), "$MA_COMPRESS_POS_TOL[X1]");
  EXPECT_EQ(md_name_of("program.start_position_mm"), "-");
  EXPECT_EQ(md_name_of("nothing.known"), "-");
}

TEST(ProfileMdNames, EveryRowOfTheEmbeddedProfile) {
  const auto rows = flatten_profile_json(profile_to_json(default_profile()));
  bool x_velocity = false;
  for (const auto& [key, value] : rows) {
    if (key == "axes.X.max_velocity_mm_min") {
      x_velocity = true;
      EXPECT_EQ(value, "40000.0");
    }
    EXPECT_FALSE(md_name_of(key).empty()) << key;
  }
  EXPECT_TRUE(x_velocity);
}

}  // namespace
}  // namespace drycut::machine
