#include "interp/tool_state.hpp"

#include <cmath>
#include <cstdlib>

namespace drycut::interp {
namespace {

constexpr int kToolNotInTable = 990012;  // drycut warning: zero offsets assumed
constexpr int kIllegalTNumber = 17190;
constexpr int kIllegalDNumber = 17180;
constexpr int kMaxNumber = 32000;  // T and D numbers

std::optional<int> tool_number(const std::string& id) {
  char* end = nullptr;
  const long n = std::strtol(id.c_str(), &end, 10);
  if (id.empty() || !end || *end != '\0' || n < 0 || n > kMaxNumber) return std::nullopt;
  return static_cast<int>(n);
}

}  // namespace

ToolState::ToolState(const machine::MachineProfile& profile)
    : table_(profile.tools),
      change_mode_(profile.tool_change_mode),
      change_m_code_(profile.tool_change_m_code),
      edge_default_(profile.cutting_edge_default),
      table_complete_(profile.tool_table_complete) {}

const machine::Tool* ToolState::find(const std::string& id) const {
  // T="name" selects by name (case-sensitive; of sister tools the lowest duplo number), T<n> by
  // number (kept as its decimal text).
  if (const machine::Tool* t = find_sister(id, 0)) return t;
  if (auto n = tool_number(id))
    for (const auto& t : table_)
      if (t.number == *n) return &t;
  return nullptr;
}

const machine::Tool* ToolState::find_sister(const std::string& name, int duplo) const {
  return machine::find_sister_tool(table_, name, duplo);
}

bool ToolState::same_tool(const std::string& a, const std::string& b) const {
  if (a == b) return true;
  const machine::Tool* tool = find(a);
  return tool && tool == find(b);
}

machine::Tool* ToolState::find_by_number(int number) {
  for (auto& t : table_)
    if (t.number == number) return &t;
  return nullptr;
}

void ToolState::missing(int number, const std::string& detail, std::vector<ToolNotice>& notices) const {
  if (table_complete_)
    notices.push_back({number, detail, true});
  else
    notices.push_back({kToolNotInTable, detail + "; length 0 and radius 0 assumed", false});
}

bool ToolState::program_tool(const std::string& id, std::vector<ToolNotice>& notices) {
  // T0 and T00 are the same empty tool.
  const std::string key = tool_number(id) ? std::to_string(*tool_number(id)) : id;
  if (key != "0" && !find(key)) missing(kIllegalTNumber, "tool " + key + " is not in the tool table", notices);
  programmed_ = key;
  change_pending_ = true;
  remembered_edge_.reset();
  return change_mode_ == 0;
}

void ToolState::select_edge(int d, std::vector<ToolNotice>& notices) {
  if (change_pending_) remembered_edge_ = d;
  // With no tool in the spindle the D waits for the prepared tool (or is D0: nothing to do).
  if (!has_tool()) {
    edge_ = d;
    offsets_ = {};
    if (d != 0 && !change_pending_)
      missing(kIllegalDNumber, "D" + std::to_string(d) + " without a tool in the spindle", notices);
    return;
  }
  // A D meant for the prepared tool may name an edge the old one lacks: no notice for that.
  std::vector<ToolNotice> ignored;
  activate_edge(d, change_pending_ ? ignored : notices);
}

void ToolState::change_tool(std::optional<int> d, std::vector<ToolNotice>& notices) {
  const int old_edge = edge_;
  const ToolOffsets old_offsets = offsets_;
  if (programmed_) active_ = programmed_;  // M6 without a new T changes to the last one again
  change_pending_ = false;
  std::optional<int> edge = d ? d : remembered_edge_;
  remembered_edge_.reset();
  if (!has_tool()) {
    edge_ = 0;
    offsets_ = {};
    return;
  }
  if (!edge) {
    // MD20270 CUTTING_EDGE_DEFAULT.
    if (edge_default_ == -2) {
      edge_ = old_edge;
      offsets_ = old_offsets;  // the old tool's offsets stay until a D is programmed
      return;
    }
    edge = edge_default_ == -1 ? old_edge : edge_default_;
  }
  activate_edge(*edge, notices);
}

void ToolState::activate_edge(int d, std::vector<ToolNotice>& notices) {
  edge_ = d;
  offsets_ = {};
  if (d == 0 || !has_tool()) return;
  const machine::Tool* tool = find(*active_);
  if (!tool) {
    // Already reported when the tool was programmed: the edge of an unknown tool is zero.
    if (table_complete_) missing(kIllegalDNumber, "tool " + *active_ + " is not in the tool table", notices);
    return;
  }
  for (const auto& e : tool->edges) {
    if (e.d == d) {
      offsets_ = ToolOffsets::of(e);
      return;
    }
  }
  missing(kIllegalDNumber, "tool " + *active_ + " has no edge D" + std::to_string(d), notices);
}

machine::Tool* ToolState::tool_for_write(int t) {
  if (t < 1 || t > kMaxNumber) return nullptr;
  if (machine::Tool* tool = find_by_number(t)) return tool;
  table_.push_back({std::to_string(t), t, {}});
  return &table_.back();
}

machine::ToolEdge* ToolState::edge_for_write(int t, int d) {
  machine::Tool* tool = d < 1 || d > kMaxNumber ? nullptr : tool_for_write(t);
  if (!tool) return nullptr;
  for (auto& e : tool->edges)
    if (e.d == d) return &e;
  tool->edges.push_back({d, 0.0, 0.0});
  return &tool->edges.back();
}

namespace {

// A geometry value written while its wear is kept: the sum is geometry + wear.
void set_geometry(double& sum, double wear, double value) { sum = value + wear; }
// A wear value written: the sum follows, the geometry part stays.
void set_wear(double& sum, double& wear, double value) {
  sum += value - wear;
  wear = value;
}

}  // namespace

ToolOffsets ToolOffsets::of(const machine::ToolEdge& e) {
  ToolOffsets o;
  o.length_mm = e.length_mm + e.base_mm[0];
  o.radius_mm = e.radius_mm;
  o.teeth = e.teeth;
  o.type = e.type;
  o.length2_mm = e.length2_mm + e.base_mm[1];
  o.length3_mm = e.length3_mm + e.base_mm[2];
  o.edge_position = e.edge_position;
  return o;
}

bool ToolState::set_edge_parameter(int parameter, int t, int d, double value) {
  if (parameter < 1 || parameter > 25) return false;
  machine::ToolEdge* edge = edge_for_write(t, d);
  if (!edge) return false;
  // The control adds each wear value to its geometry value (Fundamentals, "Tool offset data":
  // DP12..DP14 wear of lengths 1..3, DP15 wear of the radius) and the base lengths DP21..DP23 to
  // lengths 1..3 (W1, "Basic length 1 to 3"; added in ToolOffsets::of).
  switch (parameter) {
    case 1: edge->type = value >= 0 && value <= 999 ? static_cast<int>(value) : 0; break;
    case 2: edge->edge_position = value >= 0 && value <= 9 && value == std::floor(value) ? static_cast<int>(value) : 0; break;
    case 3: set_geometry(edge->length_mm, edge->length_wear_mm, value); break;
    case 4: set_geometry(edge->length2_mm, edge->length2_wear_mm, value); break;
    case 5: set_geometry(edge->length3_mm, edge->length3_wear_mm, value); break;
    case 6: set_geometry(edge->radius_mm, edge->radius_wear_mm, value); break;
    case 12: set_wear(edge->length_mm, edge->length_wear_mm, value); break;
    case 13: set_wear(edge->length2_mm, edge->length2_wear_mm, value); break;
    case 14: set_wear(edge->length3_mm, edge->length3_wear_mm, value); break;
    case 15: set_wear(edge->radius_mm, edge->radius_wear_mm, value); break;
    case 21:
    case 22:
    case 23: edge->base_mm[static_cast<size_t>(parameter - 21)] = value; break;
    default: break;
  }
  // The active offsets are not touched: new values of the active edge take effect with the next
  // D or tool change, as a change made on the operator panel (Fundamentals, "Tool radius
  // compensation", changing the compensation values; until 2026-11-30 they acted at once).
  return true;
}

bool ToolState::set_edge_teeth(int t, int d, double teeth) {
  if (!(teeth >= 0 && teeth <= kMaxNumber) || teeth != std::floor(teeth)) return false;
  machine::ToolEdge* edge = edge_for_write(t, d);
  if (!edge) return false;
  edge->teeth = static_cast<int>(teeth);
  return true;
}

bool ToolState::set_tool_name(int t, const std::string& name) {
  machine::Tool* tool = tool_for_write(t);
  if (!tool) return false;
  tool->name = name;
  return true;
}

}  // namespace drycut::interp
