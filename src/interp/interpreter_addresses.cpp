// Address words of a block with rules of their own (apply_addresses in interpreter.cpp reads
// the others): F (the feed, or the lead change of G34/G35), T (the tool, per spindle), D (the
// edge) and the tool change by an M function (MD22550 = 1).
#include <cmath>
#include <string>
#include <vector>

#include "interp/interpreter.hpp"
#include "interp/interpreter_block.hpp"

namespace drycut::interp {

using parser::AddressWord;
using namespace detail;

void Interpreter::note_tool_change_m_words(BlockContext& ctx) {
  // MD22550 = 1: the M function of MD22560 changes the tool; its address extension is a
  // spindle number, and only the master spindle (1) changes tools here (W1 2.2.5).
  if (!tools_.change_on_m_code()) return;
  for (const auto& m : ctx.block.m) {
    if (m.code != tools_.change_m_code()) continue;
    if (m.extension > 1)
      warn_once(ctx, "M" + std::to_string(m.extension) + "=" + std::to_string(m.code) +
                         ": tool change on another spindle than the master spindle 1", m.column);
    else
      ctx.tool_change = true;
  }
}

void Interpreter::change_tool_regardless_of_status(BlockContext& ctx, const parser::CommandWord& c) {
  // TCA("name", duplo, toolholder): tool management's tool change that ignores the tool's status
  // (disabled, worn): the tool is selected and changed in this block, as T="name" with the change
  // M function (Function Manual Tool Management, "TCA"). duplo selects that sister tool (0 or
  // missing: by the name, as T="name"); toolholder 0 or missing is the master spindle.
  const auto* name = c.args.empty() ? nullptr : std::get_if<std::string>(&c.args[0]);
  if (!name || name->empty()) raise(ctx, 12080, "TCA needs a tool name: TCA(\"name\", duplo, toolholder)", c.column);
  auto number_arg = [&](size_t i) {
    const auto* v = i < c.args.size() ? std::get_if<double>(&c.args[i]) : nullptr;
    return v ? *v : 0.0;
  };
  const double duplo = number_arg(1), holder = number_arg(2);
  if (!(duplo >= 0 && duplo <= kMaxToolNumber && duplo == std::floor(duplo)) ||
      !(holder >= 0 && holder <= 99 && holder == std::floor(holder)))
    raise(ctx, 12160, "TCA: duplo and toolholder must be whole numbers >= 0", c.column);
  if (holder > 0 && static_cast<int>(holder) != master_spindle()) {
    warn_once(ctx, "TCA for toolholder " + std::to_string(static_cast<int>(holder)) +
                       " (a tool for another spindle than the master: not simulated)", c.column);
    return;
  }
  std::string id = *name;
  if (duplo >= 1)
    if (const machine::Tool* sister = tools_.find_sister(*name, static_cast<int>(duplo))) id = std::to_string(sister->number);
  program_tool(ctx, id, c.column);
  ctx.tool_change = true;
}

void Interpreter::apply_feed_address(BlockContext& ctx, const AddressWord& a) {
  if (ctx.dwell) return;  // G4 F<s>: dwell time, modal feed unchanged
  // F has a resolution of 0.001: a smaller value is zero on the control (and would make
  // absurd times here).
  if (state_.motion == MotionMode::ThreadIncreasing || state_.motion == MotionMode::ThreadDecreasing) {
    // G34/G35: F is the lead change per revolution (0: constant lead).
    if (!(a.value >= 0)) raise(ctx, 12160, "the lead change F must be >= 0", a.column);
    ctx.lead_change_mm = a.value * geometry_unit();
    return;
  }
  if (a.value < kMinFeed) raise(ctx, 14800, "F" + std::to_string(a.value), a.column);
  state_.feed = a.value;
  state_.feed_type_changed = false;
  state_.feed_unit_mm = feed_unit();  // kept with F: a later G70/G71 does not convert it again
  ctx.block_feed = a.value;
  apply_f_after_tooth_feed(ctx, a);
}

void Interpreter::apply_tool_address(BlockContext& ctx, const AddressWord& a) {
  const std::string_view n = a.name;
  // T, or T<n>=t / T[n]=t: tool t for spindle n (Fundamentals, "Tool change with T command":
  // address extension = spindle number). The master spindle's is the T drycut models.
  if (n.size() > 1 && (n.size() > 3 || std::stoi(std::string(n.substr(1))) != master_spindle())) {
    warn_once(ctx, std::string(n) + "= (a tool for spindle " + std::string(n.substr(1)) + ", not the master spindle: not simulated)",
              a.column);
    return;
  }
  // Checked before the conversion: a double outside long long's range is undefined there.
  if (!(a.value >= 0 && a.value <= kMaxToolNumber) || a.value != std::floor(a.value))
    raise(ctx, 12160, "T number must be a whole number 0..32000", a.column);
  program_tool(ctx, std::to_string(static_cast<long long>(a.value)), a.column);
}

void Interpreter::apply_edge_address(BlockContext& ctx, const AddressWord& a) {
  // Range first: converting a double outside int's range is undefined behaviour.
  if (!(a.value >= 0 && a.value <= kMaxEdgeNumber) || a.value != std::floor(a.value))
    raise(ctx, 12160, "D must be a whole number >= 0", a.column);
  // In a block that changes the tool the edge belongs to the new tool: taken at the change.
  if (ctx.tool_change) return;
  std::vector<ToolNotice> notices;
  tools_.select_edge(static_cast<int>(a.value), notices);
  report_tool_notices(ctx, notices, a.column);
  speed_from_cutting_speed(ctx, a.column);  // SVC: the new edge's radius
}

}  // namespace drycut::interp
