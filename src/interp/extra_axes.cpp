#include "interp/extra_axes.hpp"

#include <algorithm>
#include <cmath>

namespace drycut::interp {
namespace {

using parser::ValueMode;

bool is_direction_mode(ValueMode mode) {
  return mode == ValueMode::Direct || mode == ValueMode::AbsolutePositive || mode == ValueMode::AbsoluteNegative;
}

const char* mode_name(ValueMode mode) {
  switch (mode) {
    case ValueMode::Direct: return "DC";
    case ValueMode::AbsolutePositive: return "ACP";
    default: return "ACN";
  }
}

// From position p to target t (both in [0, range)) the way the mode chooses.
double way(double p, double t, double range, ValueMode mode) {
  double d = t - p;
  switch (mode) {
    case ValueMode::AbsolutePositive: return d < 0 ? d + range : d;
    case ValueMode::AbsoluteNegative: return d > 0 ? d - range : d;
    case ValueMode::Direct:
      if (d > range / 2) d -= range;
      if (d <= -range / 2) d += range;
      return d;
    default: return d;  // AC inside the range: like a linear axis
  }
}

}  // namespace

double wrap_modulo(double x, double range) {
  double r = std::fmod(x, range);
  if (r < 0) r += range;
  return r >= range ? 0.0 : r;
}

ExtraAxes::ExtraAxes(const machine::MachineProfile& profile)
    : axes_(profile.extra_axes),
      position_(axes_.size(), 0.0),
      in_group_(axes_.size(), false),
      feed_weight_(axes_.size(), 1.0),
      positioning_feed_(axes_.size(), 0.0) {
  for (size_t i = 0; i < axes_.size(); ++i) positioning_feed_[i] = axes_[i].pos_velocity_mm_s;
}

int ExtraAxes::index(std::string_view name) const {
  for (size_t i = 0; i < axes_.size(); ++i)
    if (axes_[i].name == name) return static_cast<int>(i);
  return -1;
}

ExtraAxes::Travel ExtraAxes::travel_to(size_t i, double value, ValueMode mode, bool absolute, double unit) const {
  const machine::AxisData& a = axes_[i];
  const double p = position_[i];
  Travel t;
  if (is_direction_mode(mode)) {
    if (!a.rotary) {
      t.alarm = mode == ValueMode::Direct ? 16800 : mode == ValueMode::AbsolutePositive ? 16810 : 16820;
      t.detail = std::string(mode_name(mode)) + " on the linear axis " + a.name;
      return t;
    }
    const double range = a.modulo ? a.modulo_range : 360.0;
    if (a.modulo && !(value >= 0 && value < range)) {
      t.alarm = 16830;
      t.detail = a.name + "=" + mode_name(mode) + "(" + std::to_string(value) + "): modulo position outside 0 .. " +
                 std::to_string(range);
      return t;
    }
    t.travel = way(wrap_modulo(p, range), wrap_modulo(value, range), range, mode);
    return t;
  }
  // DAC/DIC: a diameter value, half of it is the axis's travel (RAC/RIC: a radius, as written).
  const bool diameter = mode == ValueMode::DiameterAbsolute || mode == ValueMode::DiameterIncremental;
  const double scale = (a.rotary ? 1.0 : unit) * (diameter ? 0.5 : 1.0);
  const bool incremental = parser::is_incremental_mode(mode) || (mode == ValueMode::Default && !absolute);
  if (incremental) {
    t.travel = value * scale;
  } else if (a.modulo) {
    const bool shortest = (a.misc_function_mask & 0x4) != 0;
    t.travel = way(p, wrap_modulo(value, a.modulo_range), a.modulo_range, shortest ? ValueMode::Direct : ValueMode::Absolute);
  } else {
    t.travel = value * scale - p;
  }
  return t;
}

void ExtraAxes::move(size_t i, double travel) {
  const machine::AxisData& a = axes_[i];
  position_[i] = a.modulo ? wrap_modulo(position_[i] + travel, a.modulo_range) : position_[i] + travel;
}

std::string ExtraAxes::set_feed_group(const std::vector<std::string>& names) {
  std::fill(in_group_.begin(), in_group_.end(), false);
  geometry_group_ = names.empty() ? 7 : 0;
  for (const auto& n : names) {
    if (n == "X" || n == "Y" || n == "Z") {
      geometry_group_ |= static_cast<uint8_t>(1u << (n[0] - 'X'));
    } else if (const int k = index(n); k >= 0) {
      in_group_[static_cast<size_t>(k)] = true;
    } else if (!n.empty()) {
      return n;
    }
  }
  // No axis of the group left (FGROUP of unknown names only): the default group.
  if (geometry_group_ == 0 && std::none_of(in_group_.begin(), in_group_.end(), [](bool b) { return b; }))
    geometry_group_ = 7;
  return {};
}

void ExtraAxes::mark_running(AsyncMove move) {
  clear_running(move.axis);
  running_.push_back(std::move(move));
}

bool ExtraAxes::running(const std::string& axis) const {
  return std::any_of(running_.begin(), running_.end(), [&](const AsyncMove& m) { return m.axis == axis; });
}

double ExtraAxes::clear_running(const std::string& axis) {
  double arrival = 0.0;
  for (const AsyncMove& m : running_)
    if (m.axis == axis) arrival = std::max(arrival, m.arrival_s);
  std::erase_if(running_, [&](const AsyncMove& m) { return m.axis == axis; });
  return arrival;
}

const ExtraAxes::AsyncMove* ExtraAxes::moving_at(const std::string& axis, double now) const {
  for (const AsyncMove& m : running_)
    if (m.axis == axis && now < m.arrival_s) return &m;
  return nullptr;
}

}  // namespace drycut::interp
