// Machine profile: the embedded default, validation errors that name their key, round trip.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "machine/machine_profile.hpp"

namespace drycut::machine {
namespace {

using nlohmann::json;

// A small valid custom profile (different from the default in every value).
json small_profile() {
  return json::parse(R"({
    "name": "test mill",
    "axes": {
      "X": {"min_mm": -10, "max_mm": 20, "max_velocity_mm_s": 100, "max_accel_mm_s2": 1000, "max_jerk_mm_s3": 20000},
      "Y": {"min_mm": -11, "max_mm": 21, "max_velocity_m_min": 12, "max_accel_m_s2": 2, "max_jerk_m_s3": 30},
      "Z": {"min_m": -0.5, "max_mm": 22, "max_velocity_mm_min": 6000, "max_accel_m_s2": 3, "max_jerk_m_s3": 40}
    },
    "path": {"ipo_cycle_ms": 2, "max_accel_ovl_factor": 1.5, "max_path_jerk_m_s3": 25,
             "soft_accel_factor": 0.8, "curv_effect_on_path_accel": 0.5, "lookahead_blocks": 7,
             "short_block_factor": 0.8, "g0_accel_factor": 1.2, "g0_jerk_factor": 1.3,
             "tool_change_time_s": 2.5},
    "program": {"reset_gcodes": ["G0", "G64"], "work_offsets_mm": {"G54": [1, 2, 3], "G505": [4, 5, 6]},
                "work_offset_rotations_deg": {"G54": [0, 0, 30], "G500": [1, 2, 3]},
                "start_position_mm": [7, 8, 9], "circle_error_const_mm": 0.02, "circle_error_factor": 0.002,
                "cubic_spline_blocks": 5, "cubic_spline_global": true,
                "cutcom_maxnum_check_blocks": 4, "cutcom_maxnum_dummy_blocks": 6,
                "cutcom_corner_limit_deg": 120, "cutcom_curve_insert_limit_deg": 25},
    "tools": [{"name": "T_A", "number": 3, "edges": [{"d": 1, "radius_mm": 5, "length_mm": 50},
                                                     {"d": 2, "radius_mm": 4}]}]
  })");
}

std::string error_of(const json& j) {
  try {
    load_profile_json(j.dump(), "test.json");
  } catch (const ProfileError& e) {
    return e.what();
  }
  return "<no error>";
}

TEST(DefaultProfile, LoadsTheMcv1210) {
  const MachineProfile& p = default_profile();
  EXPECT_NE(p.name.find("MCV 1210"), std::string::npos);
  // EXPERIMENT.md §6: 40 m/min and 5 m/s² per axis, travel 1000 / 800 / 600 mm.
  const double travel[3] = {1000, 800, 600};
  for (int i = 0; i < 3; ++i) {
    EXPECT_DOUBLE_EQ(p.axes[i].max_velocity_mm_s, 40000.0 / 60.0);
    EXPECT_DOUBLE_EQ(p.axes[i].max_accel_mm_s2, 5000.0);
    EXPECT_DOUBLE_EQ(p.axes[i].max_mm - p.axes[i].min_mm, travel[i]);
    EXPECT_GT(p.axes[i].max_jerk_mm_s3, 0.0);
  }
  EXPECT_EQ(p.axes[0].name, "X");
  EXPECT_EQ(p.axes[2].name, "Z");
  EXPECT_DOUBLE_EQ(p.ipo_cycle_s, 0.004);
  EXPECT_DOUBLE_EQ(p.max_accel_ovl_factor, 1.2);
  EXPECT_DOUBLE_EQ(p.short_block_factor, 0.9);
  EXPECT_GT(p.path_jerk_mm_s3, 0.0);
  EXPECT_GE(p.lookahead_blocks, 1);
  const Tool* fr4 = p.find_tool("FR_4");
  ASSERT_NE(fr4, nullptr);
  EXPECT_EQ(fr4->number, 1);
  ASSERT_EQ(fr4->edges.size(), 1u);
  EXPECT_EQ(fr4->edges[0].d, 1);
  EXPECT_DOUBLE_EQ(fr4->edges[0].radius_mm, 2.0);
  ASSERT_EQ(p.work_offsets.count("G54"), 1u);
  EXPECT_EQ(p.work_offsets.at("G54"), Eigen::Vector3d::Zero());
  EXPECT_EQ(p.start_position, Eigen::Vector3d(0, 0, 100));
  EXPECT_FALSE(p.reset_gcodes.empty());
}

TEST(DefaultProfile, IsTheSameObjectEachCall) { EXPECT_EQ(&default_profile(), &default_profile()); }

TEST(LoadProfile, ConvertsUnitsToMmAndSeconds) {
  MachineProfile p = load_profile_json(small_profile().dump(), "t");
  EXPECT_DOUBLE_EQ(p.axes[0].max_velocity_mm_s, 100.0);
  EXPECT_DOUBLE_EQ(p.axes[1].max_velocity_mm_s, 200.0);   // 12 m/min
  EXPECT_DOUBLE_EQ(p.axes[2].max_velocity_mm_s, 100.0);   // 6000 mm/min
  EXPECT_DOUBLE_EQ(p.axes[1].max_accel_mm_s2, 2000.0);
  EXPECT_DOUBLE_EQ(p.axes[1].max_jerk_mm_s3, 30000.0);
  EXPECT_DOUBLE_EQ(p.axes[2].min_mm, -500.0);              // -0.5 m
  EXPECT_DOUBLE_EQ(p.ipo_cycle_s, 0.002);
  EXPECT_DOUBLE_EQ(p.path_jerk_mm_s3, 25000.0);
  EXPECT_EQ(p.lookahead_blocks, 7);
  EXPECT_DOUBLE_EQ(p.tool_change_time_s, 2.5);
  EXPECT_EQ(p.work_offsets.at("G505"), Eigen::Vector3d(4, 5, 6));
  EXPECT_EQ(p.work_offset_rotations_deg.at("G54"), Eigen::Vector3d(0, 0, 30));
  EXPECT_EQ(p.work_offset_rotations_deg.at("G500"), Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(p.start_position, Eigen::Vector3d(7, 8, 9));
  EXPECT_TRUE(p.cubic_spline_global);
  ASSERT_NE(p.find_tool(3), nullptr);
  EXPECT_DOUBLE_EQ(p.find_tool(3)->edges[1].radius_mm, 4.0);
}

TEST(LoadProfile, RoundTripKeepsEveryField) {
  MachineProfile a = load_profile_json(small_profile().dump(), "t");
  MachineProfile b = load_profile_json(profile_to_json(a), "round trip");
  EXPECT_EQ(a.name, b.name);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(a.axes[i].name, b.axes[i].name);
    EXPECT_NEAR(a.axes[i].min_mm, b.axes[i].min_mm, 1e-12);
    EXPECT_NEAR(a.axes[i].max_mm, b.axes[i].max_mm, 1e-12);
    EXPECT_NEAR(a.axes[i].max_velocity_mm_s, b.axes[i].max_velocity_mm_s, 1e-9);
    EXPECT_NEAR(a.axes[i].max_accel_mm_s2, b.axes[i].max_accel_mm_s2, 1e-9);
    EXPECT_NEAR(a.axes[i].max_jerk_mm_s3, b.axes[i].max_jerk_mm_s3, 1e-6);
  }
  EXPECT_NEAR(a.ipo_cycle_s, b.ipo_cycle_s, 1e-15);
  EXPECT_EQ(a.max_accel_ovl_factor, b.max_accel_ovl_factor);
  EXPECT_NEAR(a.path_jerk_mm_s3, b.path_jerk_mm_s3, 1e-6);
  EXPECT_EQ(a.soft_accel_factor, b.soft_accel_factor);
  EXPECT_EQ(a.curv_effect_on_path_accel, b.curv_effect_on_path_accel);
  EXPECT_EQ(a.lookahead_blocks, b.lookahead_blocks);
  EXPECT_EQ(a.short_block_factor, b.short_block_factor);
  EXPECT_EQ(a.g0_accel_factor, b.g0_accel_factor);
  EXPECT_EQ(a.g0_jerk_factor, b.g0_jerk_factor);
  EXPECT_EQ(a.tool_change_time_s, b.tool_change_time_s);
  EXPECT_EQ(a.reset_gcodes, b.reset_gcodes);
  EXPECT_EQ(a.work_offsets, b.work_offsets);
  EXPECT_EQ(a.work_offset_rotations_deg, b.work_offset_rotations_deg);
  EXPECT_EQ(a.start_position, b.start_position);
  EXPECT_EQ(a.circle_error_const_mm, b.circle_error_const_mm);
  EXPECT_EQ(a.circle_error_factor, b.circle_error_factor);
  EXPECT_EQ(a.cubic_spline_blocks, b.cubic_spline_blocks);
  EXPECT_EQ(a.cubic_spline_global, b.cubic_spline_global);
  EXPECT_EQ(a.cutcom_maxnum_check_blocks, b.cutcom_maxnum_check_blocks);
  EXPECT_EQ(a.cutcom_maxnum_dummy_blocks, b.cutcom_maxnum_dummy_blocks);
  EXPECT_EQ(b.cutcom_corner_limit_deg, 120.0);
  EXPECT_EQ(b.cutcom_curve_insert_limit_deg, 25.0);
  ASSERT_EQ(a.tools.size(), b.tools.size());
  EXPECT_EQ(a.tools[0].name, b.tools[0].name);
  EXPECT_EQ(a.tools[0].number, b.tools[0].number);
  ASSERT_EQ(b.tools[0].edges.size(), 2u);
  EXPECT_EQ(b.tools[0].edges[0].length_mm, 50.0);
}

// Further axes by name (docs/axes.md): rotary ones in degrees, units converted like X's.
json profile_with_extra_axes() {
  json j = small_profile();
  j["axes"]["C"] = json::parse(R"({"rotary": true, "modulo": true, "max_velocity_rev_min": 20,
      "max_accel_deg_s2": 600, "max_jerk_rev_s3": 10, "pos_velocity_deg_s": 30, "misc_function_mask": 4})");
  j["axes"]["A"] = json::parse(R"({"rotary": true, "min_deg": -120, "max_deg": 30, "max_velocity_deg_min": 3600,
      "max_accel_deg_s2": 300, "max_jerk_deg_s3": 3000})");
  j["axes"]["U"] = json::parse(R"({"min_mm": -50, "max_mm": 50, "max_velocity_m_min": 6, "max_accel_m_s2": 2,
      "max_jerk_m_s3": 50})");
  return j;
}

TEST(LoadProfile, ReadsExtraAxesInNameOrderWithAngularUnits) {
  MachineProfile p = load_profile_json(profile_with_extra_axes().dump(), "t");
  ASSERT_EQ(p.extra_axes.size(), 3u);
  EXPECT_EQ(p.extra_axes[0].name, "A");
  EXPECT_EQ(p.extra_axes[1].name, "C");
  EXPECT_EQ(p.extra_axes[2].name, "U");
  EXPECT_EQ(p.extra_axis_index("C"), 1);
  EXPECT_EQ(p.extra_axis_index("B"), -1);
  const AxisData& c = p.extra_axes[1];
  EXPECT_TRUE(c.rotary);
  EXPECT_TRUE(c.modulo);
  EXPECT_DOUBLE_EQ(c.modulo_range, 360.0);
  EXPECT_DOUBLE_EQ(c.max_velocity_mm_s, 120.0);   // 20 rev/min = 7200 deg/min = 120 deg/s
  EXPECT_DOUBLE_EQ(c.max_jerk_mm_s3, 3600.0);     // 10 rev/s^3
  EXPECT_DOUBLE_EQ(c.pos_velocity_mm_s, 30.0);
  EXPECT_EQ(c.misc_function_mask, 4);
  EXPECT_DOUBLE_EQ(p.extra_axes[0].min_mm, -120.0);
  EXPECT_DOUBLE_EQ(p.extra_axes[0].max_velocity_mm_s, 60.0);
  EXPECT_FALSE(p.extra_axes[2].rotary);
  EXPECT_DOUBLE_EQ(p.extra_axes[2].max_velocity_mm_s, 100.0);  // 6 m/min
  EXPECT_DOUBLE_EQ(p.extra_axes[2].pos_velocity_mm_s, 10000.0 / 60.0);  // MD32060 default
}

TEST(LoadProfile, ExtraAxesRoundTrip) {
  MachineProfile a = load_profile_json(profile_with_extra_axes().dump(), "t");
  MachineProfile b = load_profile_json(profile_to_json(a), "round trip");
  ASSERT_EQ(a.extra_axes.size(), b.extra_axes.size());
  for (size_t i = 0; i < a.extra_axes.size(); ++i) {
    const AxisData &x = a.extra_axes[i], &y = b.extra_axes[i];
    EXPECT_EQ(x.name, y.name);
    EXPECT_EQ(x.rotary, y.rotary);
    EXPECT_EQ(x.modulo, y.modulo);
    EXPECT_EQ(x.misc_function_mask, y.misc_function_mask);
    EXPECT_NEAR(x.min_mm, y.min_mm, 1e-9);
    EXPECT_NEAR(x.max_velocity_mm_s, y.max_velocity_mm_s, 1e-9);
    EXPECT_NEAR(x.max_accel_mm_s2, y.max_accel_mm_s2, 1e-9);
    EXPECT_NEAR(x.max_jerk_mm_s3, y.max_jerk_mm_s3, 1e-6);
    EXPECT_NEAR(x.pos_velocity_mm_s, y.pos_velocity_mm_s, 1e-9);
  }
}

TEST(LoadProfile, DefaultRoundTrips) {
  MachineProfile b = load_profile_json(profile_to_json(default_profile()), "rt");
  EXPECT_EQ(b.tools.size(), default_profile().tools.size());
  EXPECT_NEAR(b.axes[0].max_velocity_mm_s, default_profile().axes[0].max_velocity_mm_s, 1e-9);
}

struct BadCase {
  const char* pointer;   // JSON pointer to modify
  const char* value;     // new JSON value ("<erase>" removes the key)
  const char* expected;  // text the message must contain
};

class ProfileValidation : public ::testing::TestWithParam<BadCase> {};

TEST_P(ProfileValidation, ErrorNamesTheKey) {
  const BadCase& c = GetParam();
  json j = small_profile();
  json::json_pointer ptr(c.pointer);
  if (std::string(c.value) == "<erase>") {
    j[ptr.parent_pointer()].erase(ptr.back());
  } else {
    j[ptr] = json::parse(c.value);
  }
  std::string msg = error_of(j);
  EXPECT_NE(msg.find(c.expected), std::string::npos) << "message: " << msg;
  EXPECT_EQ(msg.rfind("test.json: ", 0), 0u) << msg;
}

INSTANTIATE_TEST_SUITE_P(
    Cases, ProfileValidation,
    ::testing::Values(
        BadCase{"/axes/X/max_accel_mm_s2", "0", "axes.X.max_accel: must be > 0"},
        BadCase{"/axes/Y/max_accel_m_s2", "-5", "axes.Y.max_accel: must be > 0"},
        BadCase{"/axes/Z/max_jerk_m_s3", "\"fast\"", "axes.Z.max_jerk_m_s3: must be a number"},
        BadCase{"/axes/X/max_velocity_mm_h", "5", "axes.X.max_velocity_mm_h: unknown unit 'mm_h'"},
        BadCase{"/axes/X/max_speed_mm_s", "5", "axes.X.max_speed_mm_s: unknown key"},
        BadCase{"/axes/X/max_velocity_mm_min", "6000", "axes.X.max_velocity_mm_s: given twice (also as max_velocity_mm_min)"},
        BadCase{"/axes/X/max_velocity_mm_s", "<erase>", "axes.X.max_velocity: missing"},
        BadCase{"/axes/X/min_mm", "30", "axes.X.min: must be < max"},
        BadCase{"/axes/Y", "<erase>", "axes.Y: missing"},
        // A further axis is named by its key and needs its limits like X (docs/axes.md).
        BadCase{"/axes/A", "{}", "axes.A.max_velocity: missing"},
        BadCase{"/axes/a1", "{}", "axes.a1: an axis name is upper-case letters and digits"},
        BadCase{"/axes/X/rotary", "true", "axes.X.rotary: the geometry axes X, Y, Z are linear"},
        BadCase{"/axes/X/modulo", "true", "axes.X.modulo: only a rotary axis can be a modulo axis"},
        BadCase{"/axes", "<erase>", "axes: missing"},
        BadCase{"/path/ipo_cycle_ms", "0", "path.ipo_cycle: must be > 0"},
        BadCase{"/path/ipo_cycle_us", "4", "path.ipo_cycle_us: unknown unit 'us'"},
        BadCase{"/path/max_accel_ovl_factor", "0.9", "path.max_accel_ovl_factor: must be in [1, 10]"},
        BadCase{"/path/curv_effect_on_path_accel", "0.99", "path.curv_effect_on_path_accel: must be in [0, 0.95]"},
        BadCase{"/path/lookahead_blocks", "0", "path.lookahead_blocks: must be in [1, 100000]"},
        BadCase{"/path/lookahead_blocks", "2.5", "path.lookahead_blocks: must be an integer"},
        BadCase{"/path/soft_accel_factor", "-1", "path.soft_accel_factor: must be > 0"},
        BadCase{"/path/tool_change_time_s", "-1", "path.tool_change_time: must be >= 0"},
        BadCase{"/path/max_path_jerk_m_s3", "0", "path.max_path_jerk: must be > 0"},
        BadCase{"/path/g0_accel_factor", "0", "path.g0_accel_factor: must be > 0"},
        BadCase{"/path", "[]", "path: must be an object"},
        BadCase{"/program/reset_gcodes", "[\"G1\", 5]", "program.reset_gcodes: must be an array of non-empty strings"},
        BadCase{"/program/work_offsets_mm/G53", "[0,0,0]", "program.work_offsets_mm.G53: not a settable work offset"},
        BadCase{"/program/work_offsets_mm/G54", "[0,0]", "program.work_offsets_mm.G54: must be an array of 3 numbers"},
        BadCase{"/program/work_offset_rotations_deg/G58", "[0,0,0]", "program.work_offset_rotations_deg.G58: not a settable work offset"},
        BadCase{"/program/start_position_mm", "[0,0,\"a\"]", "program.start_position_mm: must be an array of 3 numbers"},
        BadCase{"/program/cubic_spline_blocks", "0", "program.cubic_spline_blocks: must be in [1, 1000000]"},
        BadCase{"/program/cubic_spline_global", "1", "program.cubic_spline_global: must be true or false"},
        BadCase{"/program/colour", "1", "program.colour: unknown key"},
        BadCase{"/tools/0/edges/0/radius_mm", "-2", "tools[0].edges[0].radius: must be >= 0"},
        BadCase{"/tools/0/edges/1/d", "<erase>", "tools[0].edges[1].d: missing"},
        BadCase{"/tools/0/name", "\"\"", "tools[0].name: missing or empty"},
        BadCase{"/tools/0/number", "-1", "tools[0].number: must be in [0, 32000]"},
        BadCase{"/tools/1", "{\"name\": \"T_A\", \"number\": 4, \"duplo\": 1}", "tools[1].name: tool 'T_A' duplo 1 defined twice"},
        BadCase{"/tools/1", "{\"name\": \"T_B\", \"number\": 3}", "tools[1].number: tool number 3 defined twice"},
        BadCase{"/tools/1", "{\"name\": \"T_A\", \"number\": 4, \"duplo\": 0}", "tools[1].duplo: must be in [1, 32000]"},
        BadCase{"/spindle", "{}", "spindle: unknown key"}));

TEST(LoadProfile, InvalidJsonIsAProfileError) {
  try {
    load_profile_json("{ \"axes\": ", "broken.json");
    FAIL() << "no error";
  } catch (const ProfileError& e) {
    EXPECT_NE(std::string(e.what()).find("broken.json: not valid JSON"), std::string::npos);
  }
}

TEST(LoadProfile, MissingFileGivesAClearError) {
  const std::string path = "/nonexistent/dir/machine.json";
  try {
    load_profile_file(path);
    FAIL() << "no error";
  } catch (const ProfileError& e) {
    EXPECT_EQ(std::string(e.what()), path + ": machine profile file cannot be opened");
  }
}

TEST(LoadProfile, ReadsAFile) {
  std::string path = ::testing::TempDir() + "drycut_profile_test.json";
  {
    std::ofstream out(path);
    out << small_profile().dump();
  }
  MachineProfile p = load_profile_file(path);
  EXPECT_EQ(p.name, "test mill");
  std::remove(path.c_str());
}

TEST(LoadProfile, PathJerkDefaultsToSmallestAxisJerk) {
  json j = small_profile();
  j["path"].erase("max_path_jerk_m_s3");
  MachineProfile p = load_profile_json(j.dump(), "t");
  EXPECT_DOUBLE_EQ(p.path_jerk_mm_s3, 20000.0);
}

// G group 59: the profile gives DYNPOS ... DYNPREC as factors on the DYNNORM values; a group or
// factor not given is 1, and the factors survive the round trip.
TEST(LoadProfile, DynamicGroupsAreFactorsOnTheNormValues) {
  json j = small_profile();
  j["dynamic_groups"] = {{"DYNFINISH", {{"max_ax_accel_factor", 0.6}, {"max_path_jerk_factor", 0.5}}},
                         {"DYNROUGH", {{"max_ax_jerk_factor", 2}, {"path_trans_jerk_lim_factor", 3}}}};
  const MachineProfile p = load_profile_json(j.dump(), "t");
  const auto& finish = p.dynamic_groups[static_cast<size_t>(DynamicGroup::Finish)];
  const auto& rough = p.dynamic_groups[static_cast<size_t>(DynamicGroup::Rough)];
  const auto& pos = p.dynamic_groups[static_cast<size_t>(DynamicGroup::Pos)];
  EXPECT_DOUBLE_EQ(finish.max_ax_accel, 0.6);
  EXPECT_DOUBLE_EQ(finish.max_path_jerk, 0.5);
  EXPECT_DOUBLE_EQ(finish.max_ax_jerk, 1.0);
  EXPECT_DOUBLE_EQ(rough.max_ax_jerk, 2.0);
  EXPECT_DOUBLE_EQ(rough.path_trans_jerk_lim, 3.0);
  EXPECT_DOUBLE_EQ(pos.max_ax_accel, 1.0);
  const MachineProfile back = load_profile_json(profile_to_json(p), "back");
  EXPECT_DOUBLE_EQ(back.dynamic_groups[static_cast<size_t>(DynamicGroup::Finish)].max_ax_accel, 0.6);
  EXPECT_DOUBLE_EQ(back.dynamic_groups[static_cast<size_t>(DynamicGroup::Rough)].path_trans_jerk_lim, 3.0);
}

TEST(LoadProfile, DynamicGroupErrorsNameTheKey) {
  json j = small_profile();
  j["dynamic_groups"] = {{"DYNNORM", {{"max_ax_accel_factor", 2}}}};
  EXPECT_NE(error_of(j).find("dynamic_groups.DYNNORM"), std::string::npos) << error_of(j);
  j["dynamic_groups"] = {{"DYNFAST", {{"max_ax_accel_factor", 2}}}};
  EXPECT_NE(error_of(j).find("dynamic_groups.DYNFAST: not a group"), std::string::npos) << error_of(j);
  j["dynamic_groups"] = {{"DYNPOS", {{"accel", 2}}}};
  EXPECT_NE(error_of(j).find("dynamic_groups.DYNPOS.accel"), std::string::npos) << error_of(j);
  j["dynamic_groups"] = {{"DYNPOS", {{"max_ax_accel_factor", 0}}}};
  EXPECT_NE(error_of(j).find("dynamic_groups.DYNPOS.max_ax_accel_factor"), std::string::npos) << error_of(j);
}

TEST(LoadProfile, TransverseAxisMd20100) {
  // diameter_ax_def names a path axis (MD20100 DIAMETER_AX_DEF); default none; round trip.
  EXPECT_EQ(load_profile_json(small_profile().dump(), "t").diameter_axis, "");
  json j = small_profile();
  j["program"]["diameter_ax_def"] = "X";
  const MachineProfile lathe = load_profile_json(j.dump(), "t");
  EXPECT_EQ(lathe.diameter_axis, "X");
  EXPECT_EQ(load_profile_json(profile_to_json(lathe), "round trip").diameter_axis, "X");
  j["program"]["diameter_ax_def"] = "Q";
  EXPECT_NE(error_of(j).find("program.diameter_ax_def"), std::string::npos) << error_of(j);
}

}  // namespace
}  // namespace drycut::machine
