#pragma once
// Units accepted in profile key names. A key carries its unit as a suffix
// (`max_velocity_mm_min`); the reader converts to the internal units mm, s (degrees for angles).
#include <optional>
#include <span>
#include <string_view>

namespace drycut::machine {

// The angular dimensions are those of rotary axes (internal unit: degree).
enum class Dimension { Length, Velocity, Acceleration, Jerk, Time, Angle, AngularVelocity, AngularAcceleration, AngularJerk };

struct UnitInfo {
  std::string_view suffix;  // as written after the quantity name: "mm_min"
  double to_internal;       // multiply the JSON value by this to get mm, mm/s, mm/s², mm/s³ or s
};

// The units accepted for a dimension; the first one is the canonical unit written back.
std::span<const UnitInfo> units_of(Dimension dimension);
std::optional<double> unit_factor(Dimension dimension, std::string_view suffix);
// "mm_min, mm_s, m_min, m_s": for error messages.
std::string_view unit_list(Dimension dimension);

}  // namespace drycut::machine
