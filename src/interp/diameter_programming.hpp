#pragma once
// Diameter programming for turning (G group 29 DIAMOF/DIAMON/DIAM90/DIAMCYCOF and the
// axis-specific DIAMONA[ax]/DIAMOFA[ax]/DIAM90A[ax]/DIACYCOFA[ax]/DIAMCHANA[ax], DIAMCHAN).
// The channel commands act on the transverse axis of MD20100 DIAMETER_AX_DEF, the
// axis-specific ones on the axis named. Positions of an axis in diameter mode are diameters:
// drycut halves them, so that every element stays in radius (machine) coordinates.
// Rules and sources: docs/controller-state.md, "Diameter programming".
#include <array>
#include <optional>
#include <string_view>

#include "parser/block.hpp"

namespace drycut::interp {

enum class DiameterMode {
  Off,         // DIAMOF: radius
  On,          // DIAMON: diameter, absolute and incremental
  Absolute90,  // DIAM90: diameter with G90/AC, radius with G91/IC
  CycleOff     // DIAMCYCOF: radius while a cycle runs (the display keeps the previous mode)
};

struct DiameterState {
  DiameterMode channel = DiameterMode::Off;  // G group 29
  // Per geometry axis X, Y, Z: a mode of its own (DIAMONA[ax] ...), or none: the axis follows
  // the channel if it is the transverse axis, else it is a radius axis.
  std::array<std::optional<DiameterMode>, 3> axis{};
  int transverse_axis = -1;  // MD20100 DIAMETER_AX_DEF as an index 0..2; -1: none

  DiameterMode mode(int i) const {
    if (i < 0 || i > 2) return DiameterMode::Off;
    if (const auto& own = axis[static_cast<size_t>(i)]) return *own;
    return i == transverse_axis ? channel : DiameterMode::Off;
  }
  // What a programmed position value of axis i is multiplied with to give a radius: 0.5 where
  // it is a diameter. `incremental`: G91 or IC(..) for this value.
  double position_factor(int i, bool incremental) const {
    switch (mode(i)) {
      case DiameterMode::On: return 0.5;
      case DiameterMode::Absolute90: return incremental ? 1.0 : 0.5;
      default: return 1.0;
    }
  }
  // The same for a value written with its mode: DAC/DIC are diameters, RAC/RIC radii whatever
  // the axis's mode is; other values as position_factor says.
  double value_factor(int i, parser::ValueMode written, bool incremental) const {
    using parser::ValueMode;
    if (written == ValueMode::DiameterAbsolute || written == ValueMode::DiameterIncremental) return 0.5;
    if (written == ValueMode::RadiusAbsolute || written == ValueMode::RadiusIncremental) return 1.0;
    return position_factor(i, incremental);
  }
  bool any_diameter_axis() const {
    for (int i = 0; i < 3; ++i)
      if (position_factor(i, false) != 1.0) return true;
    return false;
  }
};

// The mode a G group 29 name selects: DIAMON, DIAMOF, DIAM90, DIAMCYCOF; none for another name.
std::optional<DiameterMode> channel_diameter_mode(std::string_view name);
// The mode an axis-specific command selects: DIAMONA, DIAMOFA, DIAM90A, DIACYCOFA; none for
// another name (DIAMCHANA is not a mode: the axis follows the channel again).
std::optional<DiameterMode> axis_diameter_mode(std::string_view name);
bool is_axis_diameter_command(std::string_view name);  // the four above and DIAMCHANA

}  // namespace drycut::interp
