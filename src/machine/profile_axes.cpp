#include "machine/profile_axes.hpp"

#include <array>
#include <cctype>

#include "machine/profile_object_reader.hpp"

namespace drycut::machine {
namespace {

using nlohmann::json;
constexpr std::array<const char*, 3> kGeometryAxes{"X", "Y", "Z"};

double required_quantity(ProfileObjectReader& r, const std::string& name, Dimension d) {
  auto v = r.quantity(name, d);
  if (!v)
    throw ProfileError(r.key_path(name) + ": missing (write it as " + name + "_<unit>, unit one of " +
                       std::string(unit_list(d)) + ")");
  return *v;
}

struct AxisDimensions {
  Dimension position, velocity, acceleration, jerk;
};
constexpr AxisDimensions kLinear{Dimension::Length, Dimension::Velocity, Dimension::Acceleration, Dimension::Jerk};
constexpr AxisDimensions kRotary{Dimension::Angle, Dimension::AngularVelocity, Dimension::AngularAcceleration,
                                 Dimension::AngularJerk};

// MD30600 FIX_POINT_POS: up to four fixed points of the axis (G75 FP=1..4), an array of positions.
void read_fix_points(ProfileObjectReader& r, const char* key, AxisData& a) {
  const json* node = r.child(key);
  if (!node) return;
  if (!node->is_array() || node->empty() || node->size() > 4) r.fail(key, "must be an array of 1 to 4 positions (MD30600)");
  for (const json& v : *node) {
    if (!v.is_number()) r.fail(key, "must be an array of 1 to 4 positions (MD30600)");
    a.fix_points_mm.push_back(v.get<double>());
  }
}

AxisData read_axis(const json& node, const std::string& path, const std::string& name, bool geometry) {
  ProfileObjectReader r(node, path);
  AxisData a;
  a.name = name;
  if (auto v = r.boolean("rotary")) {
    if (*v && geometry) r.fail("rotary", "the geometry axes X, Y, Z are linear");
    a.rotary = *v;
  }
  const AxisDimensions& dim = a.rotary ? kRotary : kLinear;
  if (auto v = r.boolean("modulo")) {
    if (*v && !a.rotary) r.fail("modulo", "only a rotary axis can be a modulo axis (MD30310)");
    a.modulo = *v;
  }
  if (auto v = r.quantity("modulo_range", Dimension::Angle)) {
    if (!a.modulo) r.fail("modulo_range_deg", "only for a modulo axis (\"modulo\": true)");
    a.modulo_range = require_range(*v, 1.0, 360000.0, r.key_path("modulo_range_deg"));
  }
  if (auto v = r.integer("misc_function_mask")) {
    if (*v < 0 || *v > 0xFFFF) r.fail("misc_function_mask", "must be a bit mask 0..65535 (MD30455)");
    a.misc_function_mask = static_cast<int>(*v);
  }
  if (auto v = r.quantity("min", dim.position)) a.min_mm = *v;
  if (auto v = r.quantity("max", dim.position)) a.max_mm = *v;
  a.max_velocity_mm_s = require_positive(required_quantity(r, "max_velocity", dim.velocity), r.key_path("max_velocity"));
  a.max_accel_mm_s2 = require_positive(required_quantity(r, "max_accel", dim.acceleration), r.key_path("max_accel"));
  a.max_jerk_mm_s3 = require_positive(required_quantity(r, "max_jerk", dim.jerk), r.key_path("max_jerk"));
  a.transition_jerk_mm_s3 = a.max_jerk_mm_s3;
  if (auto v = r.quantity("transition_jerk", dim.jerk))
    a.transition_jerk_mm_s3 = require_positive(*v, r.key_path("transition_jerk"));
  if (auto v = r.quantity("pos_velocity", dim.velocity)) a.pos_velocity_mm_s = require_positive(*v, r.key_path("pos_velocity"));
  if (auto v = r.quantity("compress_pos_tol", dim.position))
    a.compress_pos_tol_mm = require_positive(*v, r.key_path("compress_pos_tol"));
  if (auto v = r.quantity("reference_point", dim.position)) a.reference_point_mm = *v;
  read_fix_points(r, a.rotary ? "fix_points_deg" : "fix_points_mm", a);
  r.reject_unknown_keys();
  if (!(a.min_mm < a.max_mm)) throw ProfileError(path + ".min: must be < max (software limit range)");
  return a;
}

// A channel axis name as programs write it: a letter, then letters or digits (A, C, U, C1, B2).
bool valid_axis_name(const std::string& name) {
  if (name.empty() || name.size() > 8 || !std::isupper(static_cast<unsigned char>(name[0]))) return false;
  for (char c : name)
    if (!std::isupper(static_cast<unsigned char>(c)) && !std::isdigit(static_cast<unsigned char>(c))) return false;
  return true;
}

}  // namespace

void read_axes(const json& node, MachineProfile& p) {
  ProfileObjectReader r(node, "axes");
  for (size_t i = 0; i < kGeometryAxes.size(); ++i) {
    const json* axis = r.child(kGeometryAxes[i]);
    if (!axis) r.fail(kGeometryAxes[i], "missing (axes X, Y and Z are required)");
    p.axes[i] = read_axis(*axis, r.key_path(kGeometryAxes[i]), kGeometryAxes[i], true);
  }
  p.extra_axes.clear();
  for (auto it = node.begin(); it != node.end(); ++it) {
    const std::string& name = it.key();
    if (name == "X" || name == "Y" || name == "Z") continue;
    if (!valid_axis_name(name)) r.fail(name, "an axis name is upper-case letters and digits, starting with a letter");
    p.extra_axes.push_back(read_axis(*r.child(name), r.key_path(name), name, false));
  }
  r.reject_unknown_keys();
}

json axes_to_json(const MachineProfile& p) {
  json axes = json::object();
  auto write = [&](const AxisData& a) {
    const char* pos = a.rotary ? "deg" : "mm";
    const char* vel = a.rotary ? "_deg_min" : "_mm_min";
    const char* acc = a.rotary ? "_deg_s2" : "_m_s2";
    const char* jrk = a.rotary ? "_deg_s3" : "_m_s3";
    const double unit = a.rotary ? 1.0 : 1000.0;  // m/s² and m/s³ for linear axes
    json o = {{std::string("min_") + pos, a.min_mm},
              {std::string("max_") + pos, a.max_mm},
              {std::string("max_velocity") + vel, a.max_velocity_mm_s * 60.0},
              {std::string("max_accel") + acc, a.max_accel_mm_s2 / unit},
              {std::string("max_jerk") + jrk, a.max_jerk_mm_s3 / unit},
              {std::string("transition_jerk") + jrk, a.transition_jerk_mm_s3 / unit},
              {std::string("pos_velocity") + vel, a.pos_velocity_mm_s * 60.0},
              {std::string("compress_pos_tol_") + pos, a.compress_pos_tol_mm}};
    if (a.rotary) o["rotary"] = true;
    if (!a.fix_points_mm.empty()) o[std::string("fix_points_") + pos] = a.fix_points_mm;
    if (a.reference_point_mm) o[std::string("reference_point_") + pos] = *a.reference_point_mm;
    if (a.misc_function_mask != 0) o["misc_function_mask"] = a.misc_function_mask;
    if (a.modulo) {
      o["modulo"] = true;
      o["modulo_range_deg"] = a.modulo_range;
    }
    axes[a.name] = o;
  };
  for (const auto& a : p.axes) write(a);
  for (const auto& a : p.extra_axes) write(a);
  return axes;
}

}  // namespace drycut::machine
