#include "interp/diameter_programming.hpp"

namespace drycut::interp {

std::optional<DiameterMode> channel_diameter_mode(std::string_view name) {
  if (name == "DIAMOF") return DiameterMode::Off;
  if (name == "DIAMON") return DiameterMode::On;
  if (name == "DIAM90") return DiameterMode::Absolute90;
  if (name == "DIAMCYCOF") return DiameterMode::CycleOff;
  return std::nullopt;
}

std::optional<DiameterMode> axis_diameter_mode(std::string_view name) {
  if (name == "DIAMOFA") return DiameterMode::Off;
  if (name == "DIAMONA") return DiameterMode::On;
  if (name == "DIAM90A") return DiameterMode::Absolute90;
  if (name == "DIACYCOFA") return DiameterMode::CycleOff;
  return std::nullopt;
}

bool is_axis_diameter_command(std::string_view name) {
  return axis_diameter_mode(name).has_value() || name == "DIAMCHANA";
}

}  // namespace drycut::interp
