// Turning words of the channel: diameter programming (G group 29 and the axis-specific
// DIAMONA[ax] ...; interp/diameter_programming.hpp) and SCC[ax], the reference axis of G96.
// Rules and sources: docs/controller-state.md, "Diameter programming" and "Turning".
#include "interp/interpreter.hpp"
#include "interp/interpreter_block.hpp"

namespace drycut::interp {

using namespace detail;

namespace {

// The axis of DIAMONA[X] / SCC[X] (the loader hands it over as the command's one argument).
std::string axis_argument(const parser::CommandWord& c) {
  if (c.args.size() != 1) return {};
  const auto* s = std::get_if<std::string>(&c.args[0]);
  return s ? *s : std::string();
}

}  // namespace

bool Interpreter::apply_turning_command(BlockContext& ctx, const parser::CommandWord& c) {
  DiameterState& d = state_.diameter;
  if (const auto mode = channel_diameter_mode(c.name)) {
    d.channel = *mode;
    // Without MD20100 the channel has no transverse axis: the command has nothing to act on.
    if (d.transverse_axis < 0 && *mode != DiameterMode::Off)
      warn_once(ctx, c.name + " without a transverse axis (machine profile diameter_ax_def, MD20100): no effect", c.column);
    return true;
  }
  if (c.name == "DIAMCHAN") {  // every axis takes the channel's mode again
    d.axis = {};
    return true;
  }
  const bool diameter_command = is_axis_diameter_command(c.name);
  if (!diameter_command && c.name != "SCC") return false;
  const std::string axis = axis_argument(c);
  const int i = axis_index(axis);
  if (i < 0) {
    if (axis.empty() || (!is_unsimulated_axis_name(axis) && extra_axes_.index(axis) < 0))
      raise(ctx, 12550, c.name + "[" + axis + "]: not an axis of the channel", c.column);
    warn_once(ctx, c.name + "[" + axis + "] (only the geometry axes X, Y, Z are modelled)", c.column);
    return true;
  }
  if (c.name == "SCC") {
    state_.cutting_speed_axis = i;
    return true;
  }
  if (c.name == "DIAMCHANA") d.axis[static_cast<size_t>(i)].reset();
  else d.axis[static_cast<size_t>(i)] = axis_diameter_mode(c.name);
  return true;
}

}  // namespace drycut::interp
