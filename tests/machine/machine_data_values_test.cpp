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

TEST(MachineDataValues, RotaryAxisDataInRevolutionsAndItsModulo) {
  // A rotary axis's MD are in rev/min, rev/s², rev/s³ (MD30300 IS_ROT_AX): 7200 deg/min is
  // 20 rev/min, 1200 deg/s² 3.333 rev/s², 12000 deg/s³ 33.33 rev/s³; POS_AX_VELO 3600 deg/min
  // is 10 rev/min. A linear axis keeps mm/min and m/s².
  MachineProfile p = default_profile();
  AxisData c;
  c.name = "C";
  c.rotary = true;
  c.modulo = true;
  c.modulo_range = 360.0;
  c.max_velocity_mm_s = 7200.0 / 60.0;
  c.pos_velocity_mm_s = 3600.0 / 60.0;
  c.max_accel_mm_s2 = 1200.0;
  c.max_jerk_mm_s3 = 12000.0;
  p.extra_axes.push_back(c);
  const auto md = machine_data_values(p);
  EXPECT_DOUBLE_EQ(md.at("$MA_MAX_AX_VELO[C1]"), 20.0);
  EXPECT_DOUBLE_EQ(md.at("$MA_POS_AX_VELO[C]"), 10.0);
  EXPECT_DOUBLE_EQ(md.at("$MA_MAX_AX_ACCEL[C1]"), 1200.0 / 360.0);
  EXPECT_DOUBLE_EQ(md.at("$MA_MAX_AX_JERK[AX4]"), 12000.0 / 360.0);
  EXPECT_DOUBLE_EQ(md.at("$MA_IS_ROT_AX[C]"), 1.0);
  EXPECT_DOUBLE_EQ(md.at("$MA_ROT_IS_MODULO[C]"), 1.0);
  EXPECT_DOUBLE_EQ(md.at("$MA_MODULO_RANGE[C]"), 360.0);
  EXPECT_DOUBLE_EQ(md.at("$MA_IS_ROT_AX[X]"), 0.0);
  EXPECT_DOUBLE_EQ(md.at("$MA_ROT_IS_MODULO[X]"), 0.0);
  EXPECT_EQ(md.count("$MA_MODULO_RANGE[X]"), 0u);
  EXPECT_DOUBLE_EQ(md.at("$MA_MAX_AX_ACCEL[X]"), 5.0);
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
