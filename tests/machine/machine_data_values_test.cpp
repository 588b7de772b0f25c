// Machine data as programs read them: the profile's fields under their MD names, and its own
// machine_data map on top.
#include <gtest/gtest.h>

#include "machine/machine_data_values.hpp"
#include "machine/machine_profile.hpp"

namespace drycut::machine {
namespace {

TEST(MachineDataValues, ProfileFieldsUnderTheirMachineDataNames) {
  const auto md = machine_data_values(default_profile());
  // The MCV 1210: 40 m/min and 5 m/s^2 per axis (docs/machine-profile.md), metric.
  EXPECT_DOUBLE_EQ(md.at("$MA_MAX_AX_VELO[X1]"), 40000.0);
  EXPECT_DOUBLE_EQ(md.at("$MA_MAX_AX_VELO[Z]"), 40000.0);
  EXPECT_DOUBLE_EQ(md.at("$MA_MAX_AX_ACCEL[Y1]"), 5.0);
  EXPECT_DOUBLE_EQ(md.at("$MN_SCALING_SYSTEM_IS_METRIC"), 1.0);
  EXPECT_DOUBLE_EQ(md.at("$MC_CUTCOM_MAXNUM_CHECK_BLOCKS"), default_profile().cutcom_maxnum_check_blocks);
}

TEST(MachineDataValues, InchBaseAndTheProfilesOwnMapWin) {
  MachineProfile p = default_profile();
  p.base_unit_inch = true;
  p.machine_data["$MA_COMPRESS_POS_TOL[X1]"] = 0.01;
  p.machine_data["$MA_MAX_AX_VELO[X1]"] = 30000;
  const auto md = machine_data_values(p);
  EXPECT_DOUBLE_EQ(md.at("$MN_SCALING_SYSTEM_IS_METRIC"), 0.0);
  EXPECT_DOUBLE_EQ(md.at("$MA_COMPRESS_POS_TOL[X1]"), 0.01);
  EXPECT_DOUBLE_EQ(md.at("$MA_MAX_AX_VELO[X1]"), 30000.0);
}

TEST(MachineDataValues, ProfileJsonReadsAndWritesTheMap) {
  MachineProfile p = default_profile();
  p.machine_data["$A_IN[3]"] = 1;
  const MachineProfile back = load_profile_json(profile_to_json(p), "<round trip>");
  EXPECT_DOUBLE_EQ(back.machine_data.at("$A_IN[3]"), 1.0);
  std::string bad = profile_to_json(default_profile());
  bad.insert(bad.rfind('}'), ", \"machine_data\": {\"MA_X\": 1}");
  EXPECT_THROW(load_profile_json(bad, "<bad>"), ProfileError);  // names start with $
}

}  // namespace
}  // namespace drycut::machine
