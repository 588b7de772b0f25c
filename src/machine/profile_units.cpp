#include "machine/profile_units.hpp"

#include <array>

namespace drycut::machine {
namespace {

constexpr std::array kLength{UnitInfo{"mm", 1.0}, UnitInfo{"m", 1000.0}, UnitInfo{"um", 0.001}};
constexpr std::array kVelocity{UnitInfo{"mm_min", 1.0 / 60.0}, UnitInfo{"mm_s", 1.0},
                               UnitInfo{"m_min", 1000.0 / 60.0}, UnitInfo{"m_s", 1000.0}};
constexpr std::array kAcceleration{UnitInfo{"m_s2", 1000.0}, UnitInfo{"mm_s2", 1.0}};
constexpr std::array kJerk{UnitInfo{"m_s3", 1000.0}, UnitInfo{"mm_s3", 1.0}};
constexpr std::array kTime{UnitInfo{"s", 1.0}, UnitInfo{"ms", 0.001}};
constexpr std::array kAngle{UnitInfo{"deg", 1.0}};
constexpr std::array kAngularVelocity{UnitInfo{"deg_min", 1.0 / 60.0}, UnitInfo{"deg_s", 1.0},
                                      UnitInfo{"rev_min", 360.0 / 60.0}};
constexpr std::array kAngularAcceleration{UnitInfo{"deg_s2", 1.0}, UnitInfo{"rev_s2", 360.0}};
constexpr std::array kAngularJerk{UnitInfo{"deg_s3", 1.0}, UnitInfo{"rev_s3", 360.0}};

}  // namespace

std::span<const UnitInfo> units_of(Dimension dimension) {
  switch (dimension) {
    case Dimension::Length: return kLength;
    case Dimension::Velocity: return kVelocity;
    case Dimension::Acceleration: return kAcceleration;
    case Dimension::Jerk: return kJerk;
    case Dimension::Time: return kTime;
    case Dimension::Angle: return kAngle;
    case Dimension::AngularVelocity: return kAngularVelocity;
    case Dimension::AngularAcceleration: return kAngularAcceleration;
    case Dimension::AngularJerk: return kAngularJerk;
  }
  return {};
}

std::optional<double> unit_factor(Dimension dimension, std::string_view suffix) {
  for (const auto& u : units_of(dimension))
    if (u.suffix == suffix) return u.to_internal;
  return std::nullopt;
}

std::string_view unit_list(Dimension dimension) {
  switch (dimension) {
    case Dimension::Length: return "mm, m, um";
    case Dimension::Velocity: return "mm_min, mm_s, m_min, m_s";
    case Dimension::Acceleration: return "m_s2, mm_s2";
    case Dimension::Jerk: return "m_s3, mm_s3";
    case Dimension::Time: return "s, ms";
    case Dimension::Angle: return "deg";
    case Dimension::AngularVelocity: return "deg_min, deg_s, rev_min";
    case Dimension::AngularAcceleration: return "deg_s2, rev_s2";
    case Dimension::AngularJerk: return "deg_s3, rev_s3";
  }
  return "";
}

}  // namespace drycut::machine
