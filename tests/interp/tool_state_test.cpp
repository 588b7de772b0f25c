// Tools and offsets: T/D/M6 with MD22550/22560/20270, missing tools, $TC_DP writes, and tool
// length compensation along the plane normal. Expected values are worked out in the comments.
#include "interp_test_support.hpp"

namespace drycut::interp::testing {
namespace {

using Eigen::Vector3d;

// T1 = FR_4 (D1 r 2, L 50), T2 = "DRILL" (D1 r 3 L 80, D2 r 4 L 90).
machine::MachineProfile two_tools() {
  auto p = test_profile();
  p.tools.push_back({"DRILL", 2, {{1, 3.0, 80.0}, {2, 4.0, 90.0}}});
  return p;
}

size_t count_warnings(const RunResult& r, int number) {
  size_t n = 0;
  for (const auto& a : r.diagnostics.items())
    if (a.severity == Severity::Warning && a.number == number) ++n;
  return n;
}

TEST(ToolState, EdgeBeforeM6BelongsToThePreparedTool) {
  // `T2 D2` with no tool in the spindle, then M6: D2 of T2 (radius 4), no alarm.
  auto r = run_program("T2 D2\nM6\nG42 G1 X10 F100\nM30\n", two_tools());
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  EXPECT_DOUBLE_EQ(r->sink.motions()[0].compensation.radius_mm, 4.0);
  // Tool 1 in the spindle, T2 D2 prepared: after M6 D2 of T2 again, not MD20270's D1.
  auto again = run_program("T1 M6\nT2 D2\nM6\nG41 G1 X10 F100\nM30\n", two_tools());
  ASSERT_FALSE(again->alarm) << again->alarm->format();
  EXPECT_DOUBLE_EQ(again->sink.motions()[0].compensation.radius_mm, 4.0);
}

TEST(ToolState, EdgeAfterANamedToolBelongsToThePreparedTool) {
  // `T="DRILL" D2` then M6 (NX/hyperMILL posts write named tools so): the D follows the T word
  // as with `T2 D2`: D2 of DRILL (radius 4) after M6, no notice about an empty spindle.
  auto r = run_program("T=\"DRILL\" D2\nM6\nG42 G1 X10 F100\nM30\n", two_tools());
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  EXPECT_EQ(count_warnings(*r, 990012), 0u);
  EXPECT_DOUBLE_EQ(r->sink.motions()[0].compensation.radius_mm, 4.0);
}

TEST(ToolState, CuttingEdgeDefaultAfterAChange) {
  auto p = two_tools();
  // MD20270 = 1: edge 1 of T2 (r 3).
  auto one = run_program("T2\nM6\nG41 G1 X10 F100\nM30\n", p);
  ASSERT_FALSE(one->alarm) << one->alarm->format();
  EXPECT_DOUBLE_EQ(one->sink.motions()[0].compensation.radius_mm, 3.0);
  // MD20270 = 0: no edge after the change (D0); G41 then compensates nothing (radius 0).
  p.cutting_edge_default = 0;
  auto none = run_program("T2\nM6\nG41 G1 X10 F100\nM30\n", p);
  ASSERT_FALSE(none->alarm) << none->alarm->format();
  EXPECT_DOUBLE_EQ(none->sink.motions()[0].compensation.radius_mm, 0.0);
  // MD20270 = -1: the old edge number stays: T2 D2 active, change to T2 again -> D2 (r 4).
  p.cutting_edge_default = -1;
  auto keep = run_program("T2 M6 D2\nT2\nM6\nG41 G1 X10 F100\nM30\n", p);
  ASSERT_FALSE(keep->alarm) << keep->alarm->format();
  EXPECT_DOUBLE_EQ(keep->sink.motions()[0].compensation.radius_mm, 4.0);  // D2 kept
  // MD20270 = -2: the old tool's offsets stay until a D: T2 D2 (r 4) then change to T1 -> r 4.
  p.cutting_edge_default = -2;
  auto old = run_program("T2 M6 D2\nT1\nM6\nG41 G1 X10 F100\nD1 X20\nM30\n", p);
  ASSERT_FALSE(old->alarm) << old->alarm->format();
  EXPECT_DOUBLE_EQ(old->sink.motions()[0].compensation.radius_mm, 4.0);
  EXPECT_DOUBLE_EQ(old->sink.motions()[1].compensation.radius_mm, 2.0);  // D1 of T1
}

TEST(ToolState, EdgeInTheG41BlockCountsForTheCompensationCheck) {
  // D0 active, `G41 D1` in one block: D1 is selected before G41 starts (radius 2).
  auto r = run_program("T1 M6 D0\nG41 D1 G1 X10 F100\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  EXPECT_DOUBLE_EQ(r->sink.motions()[0].compensation.radius_mm, 2.0);
}

TEST(ToolState, ZeroToolAndZeroEdgeAreEmpty) {
  // T00 M06 takes the tool out: no offsets, G41 is alarm 10750 (no tool).
  auto r = run_program("T1 M6\nT00 M06\nG41 G1 X10 F100\nM30\n");
  ASSERT_TRUE(r->alarm);
  EXPECT_EQ(r->alarm->number, 10750);
  EXPECT_EQ(r->alarm->where.line, 3u);
  auto d0 = run_program("T1 M6 D0\nG1 Z0 F100\nM30\n");
  ASSERT_FALSE(d0->alarm) << d0->alarm->format();
  EXPECT_DOUBLE_EQ(d0->end_position.z(), 0.0);  // D0: no length
}

TEST(ToolState, ToolMissingFromTheTableWarnsAndHasNoOffsets) {
  // T9 is not in the table: warning 990012 once, length 0 (Z0 stays Z0).
  auto r = run_program("T9 M6\nG1 Z0 F100\nT9\nM6\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  EXPECT_EQ(count_warnings(*r, 990012), 1u);
  EXPECT_DOUBLE_EQ(r->end_position.z(), 0.0);
  auto strict = test_profile();
  strict.tool_table_complete = true;
  auto alarm = run_program("G1 X1 F100\nT9 M6\nM30\n", strict);
  ASSERT_TRUE(alarm->alarm);
  EXPECT_EQ(alarm->alarm->number, 17190);
  EXPECT_EQ(alarm->alarm->where.line, 2u);
  auto edge = run_program("T1 M6 D5\nM30\n", strict);
  ASSERT_TRUE(edge->alarm);
  EXPECT_EQ(edge->alarm->number, 17180);
}

TEST(ToolState, ToolChangeModeZeroChangesOnT) {
  // MD22550 = 0: T2 changes the tool at once (one ToolChange element, no M6 needed).
  auto p = two_tools();
  p.tool_change_mode = 0;
  auto r = run_program("T2\nG41 G1 X10 F100\nM6\nM30\n", p);
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  size_t changes = 0;
  for (const auto& e : r->sink.elements) changes += e.kind == ElementKind::ToolChange;
  EXPECT_EQ(changes, 1u);  // M6 is a plain M function here
  EXPECT_DOUBLE_EQ(r->sink.motions()[0].compensation.radius_mm, 3.0);
  // MD22560 = 206: M6 does not change, M206 does.
  auto q = two_tools();
  q.tool_change_m_code = 206;
  auto m206 = run_program("T2\nM6\nM206\nG41 G1 X10 F100\nM30\n", q);
  ASSERT_FALSE(m206->alarm) << m206->alarm->format();
  changes = 0;
  for (const auto& e : m206->sink.elements) changes += e.kind == ElementKind::ToolChange;
  EXPECT_EQ(changes, 1u);
}

TEST(ToolState, M6WithAnotherSpindleNumberDoesNotChange) {
  // M1=6 addresses the master spindle 1 (change); M2=6 spindle 2 (no change, warning).
  auto r = run_program("T1\nM1=6\nT2\nM2=6\nM30\n", two_tools());
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  size_t changes = 0;
  for (const auto& e : r->sink.elements) changes += e.kind == ElementKind::ToolChange;
  EXPECT_EQ(changes, 1u);
  EXPECT_EQ(count_warnings(*r, 990002), 1u);
}

TEST(ToolState, LengthActsAlongThePlaneNormalFromTheFirstMoveOfThatAxis) {
  // T1 D1: L 50. Start Z100 (carrier, no tool). X10 does not move Z; Z0 puts the tip at 0, the
  // carrier at 50. G91 Z-10 then moves 10 down: carrier 40.
  auto r = run_program("T1 M6\nG1 X10 F100\nZ0\nG91 Z-10\nM30\n");
  ASSERT_FALSE(r->alarm) << r->alarm->format();
  auto m = r->sink.motions();
  ASSERT_EQ(m.size(), 3u);
  EXPECT_TRUE(near(m[0].curve->end(), Vector3d(10, 0, 100)));
  EXPECT_TRUE(near(m[1].curve->end(), Vector3d(10, 0, 50)));
  EXPECT_TRUE(near(m[2].curve->end(), Vector3d(10, 0, 40)));
  // Incremental first move: G91 Z-10 right after the change travels -10 + 50 = +40.
  auto inc = run_program("T1 M6\nG91 G1 Z-10 F100\nM30\n");
  ASSERT_FALSE(inc->alarm) << inc->alarm->format();
  EXPECT_DOUBLE_EQ(inc->end_position.z(), 140.0);
  // G18: the normal is Y; the length goes to Y, Z stays as programmed.
  auto g18 = run_program("G18 T1 M6\nG1 Y0 Z0 F100\nM30\n");
  ASSERT_FALSE(g18->alarm) << g18->alarm->format();
  EXPECT_TRUE(near(g18->end_position, Vector3d(0, 50, 0)));
  // D0 takes the length out with the next Z move: Z0 -> carrier 0.
  auto off = run_program("T1 M6\nG1 Z0 F100\nD0\nZ0\nM30\n");
  ASSERT_FALSE(off->alarm) << off->alarm->format();
  EXPECT_DOUBLE_EQ(off->end_position.z(), 0.0);
}

TEST(ToolState, TcDpWritesChangeTheEdge) {
  // The API the $TC_DP assignment uses: T1 D1 length 50 -> 20, radius 2 -> 5.
  auto profile = test_profile();
  CollectingSink sink;
  Diagnostics diagnostics;
  Interpreter interp(profile, sink, diagnostics);
  EXPECT_TRUE(interp.tools().set_edge_parameter(3, 1, 1, 20.0));
  EXPECT_TRUE(interp.tools().set_edge_parameter(6, 1, 1, 5.0));
  EXPECT_TRUE(interp.tools().set_edge_parameter(6, 7, 2, 1.5));  // creates T7 D2
  EXPECT_FALSE(interp.tools().set_edge_parameter(3, 0, 1, 1.0)); // T0 has no edges
  std::vector<ToolNotice> notices;
  interp.tools().program_tool("7", notices);
  EXPECT_TRUE(notices.empty());
  interp.tools().change_tool(2, notices);
  EXPECT_TRUE(notices.empty());
  EXPECT_DOUBLE_EQ(interp.tools().offsets().radius_mm, 1.5);
  interp.tools().program_tool("1", notices);
  interp.tools().change_tool(std::nullopt, notices);
  EXPECT_DOUBLE_EQ(interp.tools().offsets().length_mm, 20.0);
  EXPECT_DOUBLE_EQ(interp.tools().offsets().radius_mm, 5.0);
  EXPECT_DOUBLE_EQ(profile.tools[0].edges[0].length_mm, 50.0);  // the profile is untouched
}

TEST(ToolState, TeethTakeEffectWithTheNextSelection) {
  // $TC_DPNT[t,d] (Fundamentals, "Tooth feedrate (G95 FZ)"): the active edge keeps its number
  // of teeth until the offset is selected again (D or change); a missing edge is created.
  auto profile = test_profile();
  CollectingSink sink;
  Diagnostics diagnostics;
  Interpreter interp(profile, sink, diagnostics);
  std::vector<ToolNotice> notices;
  interp.tools().program_tool("1", notices);
  interp.tools().change_tool(1, notices);
  EXPECT_EQ(interp.tools().offsets().teeth, 0);  // not in the table: unknown
  EXPECT_TRUE(interp.tools().set_edge_teeth(1, 1, 4));
  EXPECT_EQ(interp.tools().offsets().teeth, 0);  // not yet
  interp.tools().select_edge(1, notices);
  EXPECT_EQ(interp.tools().offsets().teeth, 4);
  EXPECT_TRUE(interp.tools().set_edge_parameter(6, 1, 1, 3.0));  // a radius write keeps the teeth
  EXPECT_EQ(interp.tools().offsets().teeth, 4);
  EXPECT_TRUE(interp.tools().set_edge_teeth(1, 3, 2));  // creates D3
  interp.tools().select_edge(3, notices);
  EXPECT_TRUE(notices.empty());
  EXPECT_EQ(interp.tools().offsets().teeth, 2);
  EXPECT_FALSE(interp.tools().set_edge_teeth(1, 1, 2.5));  // whole numbers only
  EXPECT_FALSE(interp.tools().set_edge_teeth(1, 1, -1));
}

}  // namespace
}  // namespace drycut::interp::testing
