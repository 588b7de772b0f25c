// Machine data as a program reads them ($MN_..., $MA_...): values follow the profile.
#include <gtest/gtest.h>

#include "machine/machine_data_values.hpp"

namespace drycut::machine {
namespace {

TEST(MachineDataValues, ScalingSystemFollowsTheBaseUnit) {
  // MD10240 SCALING_SYSTEM_IS_METRIC: 1 for a metric base system, 0 for inch (profile base_unit).
  MachineProfile metric = default_profile();
  EXPECT_EQ(machine_data_values(metric).at("$MN_SCALING_SYSTEM_IS_METRIC"), 1.0);
  MachineProfile inch = default_profile();
  inch.base_unit_inch = true;
  EXPECT_EQ(machine_data_values(inch).at("$MN_SCALING_SYSTEM_IS_METRIC"), 0.0);
  // The profile's own machine_data map still wins.
  inch.machine_data["$MN_SCALING_SYSTEM_IS_METRIC"] = 1;
  EXPECT_EQ(machine_data_values(inch).at("$MN_SCALING_SYSTEM_IS_METRIC"), 1.0);
}

TEST(MachineDataValues, AxisLimitsUnderMachineAndGeometryAxisNames) {
  // MD36110 POS_LIMIT_PLUS of the embedded profile: X travel -500..500 mm.
  const auto md = machine_data_values(default_profile());
  EXPECT_EQ(md.at("$MA_POS_LIMIT_PLUS[X1]"), 500.0);
  EXPECT_EQ(md.at("$MA_POS_LIMIT_PLUS[X]"), 500.0);
  EXPECT_EQ(md.at("$MA_POS_LIMIT_MINUS[Y1]"), -400.0);
}

}  // namespace
}  // namespace drycut::machine
