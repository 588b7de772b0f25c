// The profile's `smoothing` object (corner smoothing, docs/smoothing.md): defaults from the
// manuals, reading, round trip, and errors that name the key.
#include <gtest/gtest.h>

#include <string>

#include <nlohmann/json.hpp>

#include "machine/machine_profile.hpp"
#include "machine/machine_data_values.hpp"

namespace drycut::machine {
namespace {

using nlohmann::json;

json with_smoothing(const json& smoothing) {
  json j = json::parse(profile_to_json(default_profile()));
  j["smoothing"] = smoothing;
  return j;
}

std::string error_of(const json& j) {
  try {
    load_profile_json(j.dump(), "s.json");
  } catch (const ProfileError& e) {
    return e.what();
  }
  return "<no error>";
}

TEST(ProfileSmoothing, DefaultsAreTheManualValues) {
  const SmoothingData& s = default_profile().smoothing;
  EXPECT_EQ(s.mode, 0);                          // MD20480: axis tolerances MD33100
  EXPECT_DOUBLE_EQ(s.contur_tol_mm, 0.05);       // SD42465
  EXPECT_FALSE(s.ignore_ovl_factor);             // MD20490
  EXPECT_DOUBLE_EQ(s.g0_tolerance_factor, 3.0);  // MD20560
  EXPECT_EQ(s.max_axispoly_per_block, 3);        // MD28520
  EXPECT_DOUBLE_EQ(s.max_block_share, 0.5);
  EXPECT_DOUBLE_EQ(s.adis_max_reduction, 0.36);
}

TEST(ProfileSmoothing, ReadsAndRoundTrips) {
  const MachineProfile p = load_profile_json(
      with_smoothing({{"smoothing_mode", 10}, {"smooth_contur_tol_mm", 0.02}, {"ignore_ovl_factor_for_adis", true},
                      {"g0_tolerance_factor", 2.5}, {"mm_max_axispoly_per_block", 5}, {"max_block_share", 0.4}})
          .dump(),
      "s.json");
  EXPECT_EQ(p.smoothing.mode, 10);
  EXPECT_DOUBLE_EQ(p.smoothing.contur_tol_mm, 0.02);
  EXPECT_TRUE(p.smoothing.ignore_ovl_factor);
  EXPECT_DOUBLE_EQ(p.smoothing.g0_tolerance_factor, 2.5);
  EXPECT_EQ(p.smoothing.max_axispoly_per_block, 5);
  EXPECT_DOUBLE_EQ(p.smoothing.max_block_share, 0.4);
  const MachineProfile back = load_profile_json(profile_to_json(p), "round trip");
  EXPECT_EQ(back.smoothing.mode, 10);
  EXPECT_DOUBLE_EQ(back.smoothing.contur_tol_mm, 0.02);
  EXPECT_TRUE(back.smoothing.ignore_ovl_factor);
  EXPECT_DOUBLE_EQ(back.smoothing.max_block_share, 0.4);
  // Programs read them under their MD names.
  const auto md = machine_data_values(p);
  EXPECT_DOUBLE_EQ(md.at("$MC_SMOOTHING_MODE"), 10);
  EXPECT_DOUBLE_EQ(md.at("$SC_SMOOTH_CONTUR_TOL"), 0.02);
  EXPECT_DOUBLE_EQ(md.at("$MC_MM_MAX_AXISPOLY_PER_BLOCK"), 5);
}

TEST(ProfileSmoothing, ErrorsNameTheKey) {
  EXPECT_NE(error_of(with_smoothing({{"smoothing_mode", 5}})).find("smoothing.smoothing_mode"), std::string::npos);
  EXPECT_NE(error_of(with_smoothing({{"smoothing_mode", 50}})).find("units and tens digit 0..4"), std::string::npos);
  EXPECT_NE(error_of(with_smoothing({{"smooth_contur_tol_mm", 0}})).find("smoothing.smooth_contur_tol"),
            std::string::npos);
  EXPECT_NE(error_of(with_smoothing({{"max_block_share", 0.6}})).find("smoothing.max_block_share"), std::string::npos);
  EXPECT_NE(error_of(with_smoothing({{"adis", 1}})).find("smoothing.adis: unknown key"), std::string::npos);
}

}  // namespace
}  // namespace drycut::machine
