#pragma once
// Tool selection and tool offsets as the control keeps them (SINUMERIK Function Manual Basic
// Functions, W1 Tool offset, 2.1 and 2.2.5; docs/controller-state.md "Tools and offsets").
//
// Model (MD names are the profile fields of the same meaning):
// - T<n> / T="name" programs a tool. With MD22550 TOOL_CHANGE_MODE = 1 (milling, the default) T
//   only prepares it and the M function MD22560 TOOL_CHANGE_M_CODE (M6) changes it; with
//   MD22550 = 0 the T word changes the tool itself. T0 is "no tool": offsets zero.
// - D<n> selects cutting edge n of the active tool, D0 switches the offsets off. A D written
//   after T and before the change (`T1 D1 ... M6`) is also remembered for the prepared tool and
//   becomes its edge at the change; with no tool in the spindle yet it is only remembered.
// - The edge after a change: D in the change block, else the remembered D, else MD20270
//   CUTTING_EDGE_DEFAULT (0 none, n > 0 edge n, -1 keep the old edge number, -2 keep the old
//   offset values until the next D).
// - A tool or edge missing from the tool table gives length 0 and radius 0 and a warning
//   (990012): the table given to drycut is often not the machine's whole TO memory. With the
//   profile's tool_table_complete it is the control's alarm: 17190 (T) or 17180 (D).
// - The offsets of the active edge: length (along the plane normal, applied by the interpreter
//   with the next motion that programs that axis) and radius (tool radius compensation).
//
// The table is a copy of the profile's: $TC_DP writes of the program change it through
// set_edge_parameter without touching the shared profile.
#include <optional>
#include <string>
#include <vector>

#include "machine/machine_profile.hpp"

namespace drycut::interp {

// Something the tool logic reports: an alarm (the block stops) or a warning.
struct ToolNotice {
  int number = 0;
  std::string detail;
  bool alarm = false;
};

// The offsets of the active edge as the control adds them (Function Manual W1, "Tool offset
// data": each wear value adds to its geometry value, each base length to its length).
struct ToolOffsets {
  double length_mm = 0.0;  // length 1: $TC_DP3 + wear $TC_DP12 + base $TC_DP21
  double radius_mm = 0.0;  // radius: $TC_DP6 + wear $TC_DP15
  int teeth = 0;           // $TC_DPNT, number of teeth (G95 FZ); 0 = not known
  int type = 0;            // $TC_DP1 tool type (0: not given, a milling tool)
  double length2_mm = 0.0; // length 2: $TC_DP4 + wear $TC_DP13 + base $TC_DP22
  double length3_mm = 0.0; // length 3: $TC_DP5 + wear $TC_DP14 + base $TC_DP23
  int edge_position = 0;   // $TC_DP2 cutting edge position (turning tools)

  static ToolOffsets of(const machine::ToolEdge& edge);
};

class ToolState {
 public:
  explicit ToolState(const machine::MachineProfile& profile);

  // The T word ("5" for T5, the name for T="name"). Returns true when it changes the tool at
  // once (MD22550 = 0); the caller then calls change_tool for this block.
  bool program_tool(const std::string& id, std::vector<ToolNotice>& notices);
  // D<n> written in a block that does not change the tool.
  void select_edge(int d, std::vector<ToolNotice>& notices);
  // The tool change (M6, or T with MD22550 = 0); `d` is a D written in the same block.
  void change_tool(std::optional<int> d, std::vector<ToolNotice>& notices);

  // $TC_DP<parameter>[t, d] = value for the tool numbered t: 1 = tool type, 2 = cutting edge
  // position, 3..5 = lengths 1..3, 6 = radius, 12..14 and 15 the wear of lengths 1..3 and of the
  // radius, added to them, 21..23 base lengths 1..3 (mm); other parameters are accepted and do
  // not change the path. A missing tool or edge is created. The active edge's offsets take the
  // new values with the next D or tool change, not at once. Returns false for a parameter or
  // index out of the control's range.
  bool set_edge_parameter(int parameter, int t, int d, double value);
  // $TC_DPNT[t, d] = teeth. As on the control (Fundamentals, "Tooth feedrate (G95 FZ)") the
  // active edge takes the new number with the next D or tool change, not at once. Returns false
  // for an index or value out of range.
  bool set_edge_teeth(int t, int d, double teeth);
  // $TC_TP2[t] = "name": the name of tool t (created when missing), so T="name" and GETT find
  // it. Returns false for a number out of range.
  bool set_tool_name(int t, const std::string& name);

  bool change_on_m_code() const { return change_mode_ == 1; }
  int change_m_code() const { return change_m_code_; }
  const std::optional<std::string>& active_tool() const { return active_; }
  const std::optional<std::string>& programmed_tool() const { return programmed_; }
  int edge() const { return edge_; }
  const ToolOffsets& offsets() const { return offsets_; }
  // A tool is in the spindle (not none, not T0).
  bool has_tool() const { return active_ && *active_ != "0"; }
  // The run's tool table entry for "5" (T5) or a name; nullptr when absent.
  const machine::Tool* find(const std::string& id) const;
  // Sister tool `duplo` of a name ($TC_TP1; 0: the lowest duplo number).
  const machine::Tool* find_sister(const std::string& name, int duplo) const;
  // Whether two selections name one tool: the same text, or T<n> and T="name" of one table entry.
  bool same_tool(const std::string& a, const std::string& b) const;

 private:
  machine::Tool* find_by_number(int number);
  // The offsets of edge d of the active tool; notices when tool or edge are not in the table.
  void activate_edge(int d, std::vector<ToolNotice>& notices);
  void missing(int number, const std::string& detail, std::vector<ToolNotice>& notices) const;
  // Tool t, created (named by its number) when missing; nullptr for a number out of range.
  machine::Tool* tool_for_write(int t);
  // Edge d of tool t, created (with a new tool) when missing; nullptr for indices out of range.
  machine::ToolEdge* edge_for_write(int t, int d);

  std::vector<machine::Tool> table_;
  int change_mode_ = 1;
  int change_m_code_ = 6;
  int edge_default_ = 1;
  bool table_complete_ = false;
  std::optional<std::string> active_;
  std::optional<std::string> programmed_;   // last T written (the tool M6 loads)
  bool change_pending_ = false;             // T written since the last change
  std::optional<int> remembered_edge_;      // D written between T and the change
  int edge_ = 0;
  ToolOffsets offsets_;
};

}  // namespace drycut::interp
