// Machine data import: the MD text file tests/machine/data/mill_4axis_md.txt (written by hand in
// the control's MD file format) → a profile whose values are checked against hand-converted
// units; missing data reported; unmapped data kept under machine_data; round trip through the
// profile loader. Expected values are converted by hand in the comments.
#include <gtest/gtest.h>

#include <algorithm>

#include "machine/machine_data_file.hpp"
#include "machine/machine_data_import.hpp"
#include "machine/machine_data_values.hpp"
#include "machine/machine_profile.hpp"

namespace drycut::machine {
namespace {

const std::string kFile = DRYCUT_TEST_DIR "/machine/data/mill_4axis_md.txt";

MachineDataImport import_test_file() {
  MachineDataText text;
  read_machine_data_file(kFile, text);
  return import_machine_data(text, "mill");
}

MachineDataImport import_text(const std::string& md) {
  MachineDataText text;
  parse_machine_data_text(md, "md.txt", text);
  return import_machine_data(text, "t");
}

bool any_contains(const std::vector<std::string>& lines, const std::string& part) {
  return std::any_of(lines.begin(), lines.end(),
                     [&](const std::string& l) { return l.find(part) != std::string::npos; });
}

TEST(MachineDataFile, LineFormsOfTheControl) {
  MachineDataText t;
  parse_machine_data_text(
      "%_N_AX_TEA\n;$PATH=/_N_AX_TEA_DIR\n"
      "N32000 $MA_MAX_AX_VELO[AX1]=30000 '5A3C\n"  // MD number in front, line checksum behind
      "$ma_max_ax_accel[0,x1] = 2.5 ; comment\n"   // lower case, blanks, comment
      "$MA_MISC_FUNCTION_MASK[AX4]='H1C'\n"        // hex: 0x1C = 28
      "$MA_FOO[AX4]='B101'\n"                      // binary: 5
      "$MN_AXCONF_MACHAX_NAME_TAB[0]=\"X1\"\n"
      "$MA_IS_ROT_AX[AX4]=TRUE\n"
      "CHANDATA(2)\n$MC_CUTCOM_MAXNUM_CHECK_BLOCKS=9\n"
      "this is no machine datum\nM17\n",
      "f.txt", t);
  ASSERT_EQ(t.data.size(), 7u);
  EXPECT_EQ(t.data[0].full_name(), "$MA_MAX_AX_VELO");
  EXPECT_EQ(t.data[0].index, std::vector<std::string>{"AX1"});
  EXPECT_DOUBLE_EQ(std::get<double>(t.data[0].value), 30000.0);
  EXPECT_EQ(t.data[0].location(), "f.txt:3");
  EXPECT_EQ(t.data[1].name, "MAX_AX_ACCEL");
  EXPECT_EQ(t.data[1].index, (std::vector<std::string>{"0", "X1"}));
  EXPECT_DOUBLE_EQ(std::get<double>(t.data[1].value), 2.5);
  EXPECT_DOUBLE_EQ(std::get<double>(t.data[2].value), 28.0);
  EXPECT_DOUBLE_EQ(std::get<double>(t.data[3].value), 5.0);
  EXPECT_EQ(std::get<std::string>(t.data[4].value), "X1");
  EXPECT_DOUBLE_EQ(std::get<double>(t.data[5].value), 1.0);
  EXPECT_EQ(t.data[6].channel, 2);
  ASSERT_EQ(t.not_understood.size(), 1u);
  EXPECT_EQ(t.not_understood[0].rfind("f.txt:11:", 0), 0u);
}

TEST(MachineDataImport, LinearAxesInTheProfilesUnits) {
  const MachineProfile p = import_test_file().profile;
  // X: MD32000 30000 mm/min = 500 mm/s; MD32300 2.5 m/s² = 2500 mm/s²; MD32431 50 m/s³;
  // MD32432 200 m/s³; MD36100/36110 ±420 mm.
  EXPECT_DOUBLE_EQ(p.axes[0].max_velocity_mm_s, 500.0);
  EXPECT_DOUBLE_EQ(p.axes[0].max_accel_mm_s2, 2500.0);
  EXPECT_DOUBLE_EQ(p.axes[0].max_jerk_mm_s3, 50000.0);
  EXPECT_DOUBLE_EQ(p.axes[0].transition_jerk_mm_s3, 200000.0);
  EXPECT_DOUBLE_EQ(p.axes[0].min_mm, -420.0);
  EXPECT_DOUBLE_EQ(p.axes[0].max_mm, 420.0);
  // Y addressed by its machine axis name Y1 in the file: same values, limits ±320.
  EXPECT_DOUBLE_EQ(p.axes[1].max_accel_mm_s2, 2500.0);
  EXPECT_DOUBLE_EQ(p.axes[1].max_mm, 320.0);
  // Z: 24000 mm/min = 400 mm/s, 2 m/s², 40 m/s³, -500 .. 5 mm.
  EXPECT_DOUBLE_EQ(p.axes[2].max_velocity_mm_s, 400.0);
  EXPECT_DOUBLE_EQ(p.axes[2].max_jerk_mm_s3, 40000.0);
  EXPECT_DOUBLE_EQ(p.axes[2].max_mm, 5.0);
}

TEST(MachineDataImport, RotaryModuloAxisFromRevolutions) {
  const MachineProfile p = import_test_file().profile;
  ASSERT_EQ(p.extra_axes.size(), 1u);  // C; the spindle SP (MD35000 set) is no path axis
  const AxisData& c = p.extra_axes[0];
  EXPECT_EQ(c.name, "C");
  EXPECT_TRUE(c.rotary);
  EXPECT_TRUE(c.modulo);
  EXPECT_DOUBLE_EQ(c.modulo_range, 360.0);
  EXPECT_EQ(c.misc_function_mask, 4);                           // 'H4'
  EXPECT_DOUBLE_EQ(c.max_velocity_mm_s, 25.0 * 360 / 60);       // 25 rev/min = 9000 deg/min = 150 deg/s
  EXPECT_DOUBLE_EQ(c.max_accel_mm_s2, 1.5 * 360);               // 1.5 rev/s² = 540 deg/s²
  EXPECT_DOUBLE_EQ(c.max_jerk_mm_s3, 50.0 * 360);               // 50 rev/s³ = 18000 deg/s³
  EXPECT_DOUBLE_EQ(c.pos_velocity_mm_s, 20.0 * 360 / 60);       // 20 rev/min = 7200 deg/min
  EXPECT_DOUBLE_EQ(c.transition_jerk_mm_s3, c.max_jerk_mm_s3);  // MD32432 missing: = jerk
}

TEST(MachineDataImport, PathChannelAndSpindleData) {
  const MachineProfile p = import_test_file().profile;
  EXPECT_NEAR(p.ipo_cycle_s, 0.006, 1e-15);        // MD10050 0.002 s × MD10070 3
  EXPECT_DOUBLE_EQ(p.max_accel_ovl_factor, 1.15);  // smallest of X 1.2, Y 1.2, Z 1.15
  EXPECT_DOUBLE_EQ(p.path_jerk_mm_s3, 30000.0);    // MD20600[0] 30 m/s³
  EXPECT_EQ(p.cutcom_maxnum_check_blocks, 4);      // channel 1's 4, not channel 2's 9
  EXPECT_DOUBLE_EQ(p.circle_error_const_mm, 0.02);
  EXPECT_FALSE(p.base_unit_inch);
  EXPECT_EQ(p.tool_change_mode, 1);
  EXPECT_EQ(p.tool_change_m_code, 6);
  EXPECT_EQ(p.cutting_edge_default, 1);
  // Master spindle 5 = machine axis AX5 (MD35000 = 5): MD35100, MD35300, gear stage 1 of 35200/35210.
  EXPECT_DOUBLE_EQ(p.max_spindle_speed_rpm, 12000.0);
  EXPECT_DOUBLE_EQ(p.spindle_posctrl_velo_rpm, 400.0);
  EXPECT_DOUBLE_EQ(p.spindle_speedctrl_accel_rev_s2, 50.0);
  EXPECT_DOUBLE_EQ(p.spindle_posctrl_accel_rev_s2, 40.0);
}

TEST(MachineDataImport, SettableFramesFromTheFrameBackup) {
  const MachineDataImport r = import_test_file();
  const MachineProfile& p = r.profile;
  // G54 = $P_UIFR[1]: translation plus fine offset on Z (-402.25 + 0.05); G55 = $P_UIFR[2]: 90° about Z.
  ASSERT_EQ(p.work_offsets.count("G54"), 1u);
  EXPECT_DOUBLE_EQ(p.work_offsets.at("G54").x(), -250.5);
  EXPECT_DOUBLE_EQ(p.work_offsets.at("G54").y(), -180.0);
  EXPECT_DOUBLE_EQ(p.work_offsets.at("G54").z(), -402.2);
  EXPECT_DOUBLE_EQ(p.work_offset_rotations_deg.at("G55").z(), 90.0);
  EXPECT_EQ(p.work_offsets.count("G55"), 0u);
  EXPECT_DOUBLE_EQ(p.machine_data.at("$P_UIFR[1,X,SC]"), 1.0);  // scale: not modelled, kept
  EXPECT_EQ(r.sources.at("program.work_offset_rotations_deg.G55").origin, kFile + ":97");
}

TEST(MachineDataImport, ToolOffsetsAndSwivelTypeFromTheToolData) {
  const MachineDataImport r = import_test_file();
  const MachineProfile& p = r.profile;
  ASSERT_EQ(p.tools.size(), 2u);
  const Tool* mill = p.find_tool("FR_10");
  ASSERT_NE(mill, nullptr);
  EXPECT_EQ(mill->number, 1);
  ASSERT_EQ(mill->edges.size(), 2u);
  // Geometry plus wear: length 92.5 - 0.02, radius 5 - 0.01.
  EXPECT_NEAR(mill->edges[0].length_mm, 92.48, 1e-12);
  EXPECT_NEAR(mill->edges[0].radius_mm, 4.99, 1e-12);
  EXPECT_EQ(mill->edges[1].d, 2);
  EXPECT_DOUBLE_EQ(mill->edges[1].radius_mm, 4.5);
  const Tool* drill = p.find_tool(7);
  ASSERT_NE(drill, nullptr);
  EXPECT_EQ(drill->name, "DRILL_8");
  EXPECT_DOUBLE_EQ(drill->edges.at(0).length_mm, 120.0);
  EXPECT_EQ(p.swivel_kinematics, "head");  // $TC_CARR23[1] = "T": the tool turns
  EXPECT_DOUBLE_EQ(p.machine_data.at("$TC_DP1[1,1]"), 120.0);  // tool type: kept
  EXPECT_EQ(mill->edges[0].type, 120);                            // and the edge's type
  EXPECT_EQ(r.sources.at("tools[0].edges[0].length_mm").origin, kFile + ":104");
}

TEST(MachineDataImport, TurningToolLengthsWearBaseAndEdgePosition) {
  // A tool data backup of a turning tool: each length is geometry + wear (60 - 0.2, 5 + 0.3), the
  // base lengths and the cutting edge position are kept per edge.
  const MachineDataImport r = import_text(
      "$TC_DP1[3,1]=500\n$TC_DP2[3,1]=3\n$TC_DP3[3,1]=40\n$TC_DP4[3,1]=60\n$TC_DP5[3,1]=5\n"
      "$TC_DP13[3,1]=-0.2\n$TC_DP14[3,1]=0.3\n$TC_DP21[3,1]=1\n$TC_DP23[3,1]=2.5\n");
  const Tool* tool = r.profile.find_tool(3);
  ASSERT_NE(tool, nullptr);
  const ToolEdge& e = tool->edges.at(0);
  EXPECT_DOUBLE_EQ(e.length_mm, 40.0);
  EXPECT_NEAR(e.length2_mm, 59.8, 1e-12);
  EXPECT_NEAR(e.length3_mm, 5.3, 1e-12);
  EXPECT_DOUBLE_EQ(e.base_mm[0], 1.0);
  EXPECT_DOUBLE_EQ(e.base_mm[1], 0.0);
  EXPECT_DOUBLE_EQ(e.base_mm[2], 2.5);
  EXPECT_EQ(e.edge_position, 3);
}

TEST(MachineDataImport, SourcesNameTheDatumAndLine) {
  const MachineDataImport r = import_test_file();
  const ValueSource& v = r.sources.at("axes.X.max_velocity_mm_min");
  EXPECT_EQ(v.datum, "$MA_MAX_AX_VELO[AX1]");
  EXPECT_EQ(v.origin, kFile + ":51");
  EXPECT_EQ(r.sources.at("axes.C.max_velocity_deg_min").origin, kFile + ":77");
  EXPECT_EQ(r.sources.at("path.curv_effect_on_path_accel").origin, "default");
  EXPECT_EQ(r.sources.at("path.lookahead_blocks").origin, "default");
  // The source map survives its JSON form.
  const auto back = load_sources_json(sources_to_json(r));
  EXPECT_EQ(back.at("axes.X.max_velocity_mm_min").origin, kFile + ":51");
}

TEST(MachineDataImport, MissingValuesAreReportedWithTheirDefault) {
  const MachineDataImport r = import_test_file();
  EXPECT_TRUE(any_contains(
      r.missing, "MD20602 CURV_EFFECT_ON_PATH_ACCEL (path.curv_effect_on_path_accel): not in the files, default 0.75"));
  EXPECT_TRUE(any_contains(r.missing, "axis X (machine axis AX1) MD32060 POS_AX_VELO"));
  EXPECT_TRUE(any_contains(r.missing, "axis C (machine axis AX4) MD32432 PATH_TRANS_JERK_LIM"));
  EXPECT_FALSE(any_contains(r.missing, "MAX_AX_VELO"));
  EXPECT_TRUE(any_contains(r.notes, "channel 2"));
  EXPECT_TRUE(any_contains(r.notes, "mill_4axis_md.txt:88: THIS LINE IS NOT MACHINE DATA"));
  EXPECT_TRUE(any_contains(r.notes, "MD32310 MAX_ACCEL_OVL_FACTOR differs"));
}

TEST(MachineDataImport, CornerSmoothingData) {
  const MachineDataImport r = import_text(
      "CHANDATA(1)\n$MC_SMOOTHING_MODE=10\n$SC_SMOOTH_CONTUR_TOL=0.02\n$MC_IGNORE_OVL_FACTOR_FOR_ADIS=TRUE\n"
      "$MC_G0_TOLERANCE_FACTOR=2\n$MC_MM_MAX_AXISPOLY_PER_BLOCK=5\n");
  EXPECT_EQ(r.profile.smoothing.mode, 10);
  EXPECT_DOUBLE_EQ(r.profile.smoothing.contur_tol_mm, 0.02);
  EXPECT_TRUE(r.profile.smoothing.ignore_ovl_factor);
  EXPECT_DOUBLE_EQ(r.profile.smoothing.g0_tolerance_factor, 2.0);
  EXPECT_EQ(r.profile.smoothing.max_axispoly_per_block, 5);
  EXPECT_TRUE(any_contains(r.missing, "SD42466 SMOOTH_ORI_TOL"));  // not given: default, reported
}

TEST(MachineDataImport, RequiredAxisValuesMissingTakeTheFallback) {
  // Only X's velocity: everything else of the axes is missing and reported; the IPO cycle too.
  const MachineDataImport r = import_text("$MA_MAX_AX_VELO[AX1]=12000\n");
  EXPECT_DOUBLE_EQ(r.profile.axes[0].max_velocity_mm_s, 200.0);  // 12000 mm/min
  EXPECT_DOUBLE_EQ(r.profile.axes[1].max_velocity_mm_s, 10000.0 / 60);
  EXPECT_DOUBLE_EQ(r.profile.axes[0].max_accel_mm_s2, 1000.0);  // 1 m/s²
  EXPECT_TRUE(any_contains(r.missing,
                           "axis Y (machine axis AX2) MD32000 MAX_AX_VELO (axes.Y.max_velocity_mm_min): not in the "
                           "files, default 10000 mm/min"));
  EXPECT_TRUE(any_contains(r.missing, "axis X (machine axis AX1) MD32300 MAX_AX_ACCEL"));
  EXPECT_TRUE(any_contains(
      r.missing, "MD10050 SYSCLOCK_CYCLE_TIME MD10070 IPO_SYSCLOCK_TIME_RATIO not in the files, default 4 ms"));
  EXPECT_TRUE(any_contains(r.missing, "MD20070 $MC_AXCONF_MACHAX_USED"));
  EXPECT_DOUBLE_EQ(r.profile.ipo_cycle_s, 0.004);
}

TEST(MachineDataImport, TransverseAxisFromMd20100) {
  // MD20100 names the control's geometry axis; geometry axis 1 is called "XL" there: the profile's X.
  const MachineDataImport lathe = import_text("$MC_AXCONF_GEOAX_NAME_TAB[0]=\"XL\"\n$MC_DIAMETER_AX_DEF=\"XL\"\n");
  EXPECT_EQ(lathe.profile.diameter_axis, "X");
  EXPECT_EQ(lathe.sources.at("program.diameter_ax_def").datum, "$MC_DIAMETER_AX_DEF");
  const MachineDataImport odd = import_text("$MC_DIAMETER_AX_DEF=\"Q\"\n");
  EXPECT_EQ(odd.profile.diameter_axis, "");
  EXPECT_TRUE(any_contains(odd.notes, "not a geometry axis"));
}

TEST(MachineDataImport, UnmappedDataKeptUnderMachineDataByTheirProgramName) {
  const MachineDataImport r = import_test_file();
  const auto& md = r.profile.machine_data;
  EXPECT_DOUBLE_EQ(md.at("$MN_MM_NUM_GUD_MODULES"), 7.0);
  EXPECT_DOUBLE_EQ(md.at("$MC_MM_NUM_R_PARAM"), 300.0);
  EXPECT_DOUBLE_EQ(md.at("$MA_GEAR_STEP_SPEEDCTRL_ACCEL[0,SP1]"), 30.0);  // gear stage 0: not the one used
  EXPECT_EQ(md.count("$MA_MAX_AX_VELO[X1]"), 0u);  // mapped data are answered from the profile fields
  EXPECT_EQ(r.kept, static_cast<int>(md.size()));
  // MD33100 is mapped: the compressor tolerance of X (written with the machine axis name X1).
  EXPECT_EQ(md.count("$MA_COMPRESS_POS_TOL[X1]"), 0u);
  EXPECT_DOUBLE_EQ(r.profile.axes[0].compress_pos_tol_mm, 0.01);
  EXPECT_EQ(r.sources.at("axes.X.compress_pos_tol_mm").origin, kFile + ":58");
  // Programs read both through the one map: profile fields under their MD names plus the rest.
  const auto values = machine_data_values(r.profile);
  EXPECT_DOUBLE_EQ(values.at("$MA_MAX_AX_VELO[X1]"), 30000.0);
  EXPECT_DOUBLE_EQ(values.at("$MA_COMPRESS_POS_TOL[X1]"), 0.01);
}

TEST(MachineDataImport, RoundTripThroughTheLoader) {
  const MachineProfile p = import_test_file().profile;
  const MachineProfile back = load_profile_json(profile_to_json(p), "<round trip>");
  EXPECT_EQ(profile_to_json(back), profile_to_json(p));
  EXPECT_DOUBLE_EQ(back.extra_axes.at(0).max_velocity_mm_s, 150.0);
  EXPECT_DOUBLE_EQ(back.axes[2].max_accel_mm_s2, 2000.0);
}

TEST(MachineDataImport, AxisAssignmentAndInchBase) {
  // Channel axis 1 runs on machine axis 2 and the other way round; the profile's X is AX2.
  const MachineDataImport r = import_text(
      "$MN_SCALING_SYSTEM_IS_METRIC=0\nCHANDATA(1)\n"
      "$MC_AXCONF_MACHAX_USED[0]=2\n$MC_AXCONF_MACHAX_USED[1]=1\n$MC_AXCONF_MACHAX_USED[2]=3\n"
      "$MA_MAX_AX_VELO[AX1]=6000\n$MA_MAX_AX_VELO[AX2]=18000\n");
  EXPECT_TRUE(r.profile.base_unit_inch);
  EXPECT_DOUBLE_EQ(r.profile.axes[0].max_velocity_mm_s, 300.0);  // X on AX2: 18000 mm/min
  EXPECT_DOUBLE_EQ(r.profile.axes[1].max_velocity_mm_s, 100.0);  // Y on AX1: 6000 mm/min
}

TEST(MachineDataImport, InvalidValuesFailTheProfileValidation) {
  EXPECT_THROW(import_text("$MA_MAX_AX_VELO[AX1]=0\n"), ProfileError);
  EXPECT_THROW(import_text("$MA_POS_LIMIT_MINUS[AX1]=10\n$MA_POS_LIMIT_PLUS[AX1]=-10\n"), ProfileError);
}

TEST(MachineDataImport, HostileInputNeverCrashes) {
  // Out-of-range numbers for counts and masks, NaN and infinity, unclosed brackets and strings,
  // binary bytes: the import refuses values or reports lines, it never converts out of range.
  std::string garbage =
      "$MC_AXCONF_MACHAX_USED[0]=1e300\n$MC_SPIND_DEF_MASTER_SPIND=-1e300\n"
      "$MA_MISC_FUNCTION_MASK[AX1]=1e40\n$MA_MAX_AX_VELO[AX1]=nan\n$MA_MAX_AX_VELO[AX2]=inf\n"
      "$MA_MAX_AX_VELO[AX99999999999]=5\n$MA_X[AX1=1\n$MN_Y=\"open\n'HFFFFFFFFFFFFFFFFFFFF'\n";
  garbage += std::string("\0\x01\xff$\n$_=1\n$MN_=2\nCHANDATA(1e9)\n", 28);
  MachineDataText text;
  parse_machine_data_text(garbage, "g.txt", text);
  EXPECT_FALSE(text.not_understood.empty());
  try {
    const MachineDataImport r = import_machine_data(text, "g");
    EXPECT_DOUBLE_EQ(r.profile.axes[1].max_velocity_mm_s, 10000.0 / 60);  // inf refused: default
  } catch (const ProfileError&) {
    // A value the profile refuses is a clean error, which is also fine.
  }
}

// The elements 1..5 of the dynamic data become factors on element 0: per axis datum the smallest
// ratio over X, Y, Z. Hand computation: MD32300 element 4 (DYNFINISH) X 1.5 / 3 = 0.5, Y 2 / 2.5 =
// 0.8, Z 1 / 2 = 0.5 -> 0.5; MD20600 element 2 (DYNROUGH) 40 / 20 = 2.
TEST(MachineDataImport, DynamicGroupFactorsFromTheArrayElements) {
  const MachineProfile p = import_text(
      "$MA_MAX_AX_ACCEL[0,AX1]=3\n$MA_MAX_AX_ACCEL[0,AX2]=2.5\n$MA_MAX_AX_ACCEL[0,AX3]=2\n"
      "$MA_MAX_AX_ACCEL[4,AX1]=1.5\n$MA_MAX_AX_ACCEL[4,AX2]=2\n$MA_MAX_AX_ACCEL[4,AX3]=1\n"
      "$MC_MAX_PATH_JERK[0]=20\n$MC_MAX_PATH_JERK[2]=40\n").profile;
  EXPECT_DOUBLE_EQ(p.dynamic_groups[static_cast<size_t>(DynamicGroup::Finish)].max_ax_accel, 0.5);
  EXPECT_DOUBLE_EQ(p.dynamic_groups[static_cast<size_t>(DynamicGroup::Rough)].max_path_jerk, 2.0);
  EXPECT_DOUBLE_EQ(p.dynamic_groups[static_cast<size_t>(DynamicGroup::Rough)].max_ax_accel, 1.0);
  EXPECT_DOUBLE_EQ(p.dynamic_groups[static_cast<size_t>(DynamicGroup::Pos)].max_ax_jerk, 1.0);
}

}  // namespace
}  // namespace drycut::machine
