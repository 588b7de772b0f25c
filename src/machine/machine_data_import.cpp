#include "machine/machine_data_import.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <optional>
#include <set>

#include <nlohmann/json.hpp>

#include "machine/profile_md_names.hpp"

namespace drycut::machine {
namespace {

// Siemens' default channel axis names (MD20080) for channel axes the files do not name.
constexpr std::array<const char*, 8> kDefaultChannelAxisNames{"X", "Y", "Z", "A", "B", "C", "U", "V"};
constexpr std::array<const char*, 3> kGeometry{"X", "Y", "Z"};

// Unit factors: control unit -> profile internal unit (mm, mm/s, mm/s², mm/s³, degrees).
struct AxisUnits {
  double velocity, accel, jerk;
  const char *velocity_text, *accel_text, *jerk_text;
};
constexpr AxisUnits kLinearUnits{1.0 / 60.0, 1000.0, 1000.0, "mm/min", "m/s²", "m/s³"};
constexpr AxisUnits kRotaryUnits{360.0 / 60.0, 360.0, 360.0, "rev/min", "rev/s²", "rev/s³"};

std::string upper_text(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

std::string format_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

bool all_digits(const std::string& s) {
  return !s.empty() && s.size() < 6 && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// A datum used as a count, number or mask: rounded and clamped, so no value converts out of range.
int to_int(double v) { return static_cast<int>(std::lround(std::clamp(v, -1.0e9, 1.0e9))); }

bool is_axis_area(const std::string& area) { return area == "MA" || area == "SA" || area == "MAS" || area == "SAS"; }

bool is_channel_area(const std::string& area) { return area == "MC" || area == "SC" || area == "MCS" || area == "SCS"; }

class Importer {
 public:
  Importer(const MachineDataText& text, MachineDataImport& out) : out_(out) { index(text); }

  void run() {
    MachineProfile& p = out_.profile;
    read_configuration();
    for (size_t g = 0; g < 3; ++g) {
      p.axes[g].name = kGeometry[g];
      read_axis(machine_axis_of_channel_axis(geo_channel_axis_[g]), true, p.axes[g]);
    }
    read_extra_axes();
    read_geometry_axis_factors();
    read_nc_and_channel();
    read_dynamic_group_factors();
    read_spindle();
    read_reset_gcodes();
    read_settable_frames();
    read_tools();
    read_swivel_kinematics();
    read_transverse_axis();
    keep_the_rest();
  }

 private:
  struct Slot {
    const MachineDatum* datum;
    bool used = false;
  };

  // --- indexing -------------------------------------------------------------------------------

  // Machine axis number of an index element: AXn, or a name from MD10000; 0 if not an axis.
  int axis_number(const std::string& element) const {
    if (element.rfind("AX", 0) == 0 && all_digits(element.substr(2))) return std::stoi(element.substr(2));
    for (const auto& [k, name] : machine_axis_names_)
      if (name == element) return k;
    return 0;
  }

  void index(const MachineDataText& text) {
    for (const MachineDatum& d : text.data)
      if (d.area == "MN" && d.name == "AXCONF_MACHAX_NAME_TAB" && d.index.size() == 1 && all_digits(d.index[0]))
        if (auto* s = std::get_if<std::string>(&d.value))
          machine_axis_names_[std::stoi(d.index[0]) + 1] = upper_text(*s);
    std::set<int> other_channels;
    for (const MachineDatum& d : text.data) {
      if (is_channel_area(d.area) && d.channel != 1) {
        other_channels.insert(d.channel);
        continue;
      }
      std::string key = d.full_name();
      if (!d.index.empty()) {
        key += '[';
        for (size_t i = 0; i < d.index.size(); ++i) {
          const int axis = is_axis_area(d.area) ? axis_number(d.index[i]) : 0;
          if (axis > 0) axes_seen_.insert(axis);
          key += (i ? "," : "") + (axis > 0 ? "#" + std::to_string(axis) : d.index[i]);
        }
        key += ']';
      }
      slots_[key] = Slot{&d};  // a later line for the same datum wins, as on reading in
    }
    for (int c : other_channels)
      out_.notes.push_back("channel " + std::to_string(c) +
                           ": its channel data are not imported (drycut models channel 1)");
    for (const std::string& line : text.not_understood) out_.notes.push_back("not machine data, skipped: " + line);
  }

  // --- lookup ---------------------------------------------------------------------------------

  const MachineDatum* peek(const std::string& key) const {
    auto it = slots_.find(key);
    return it == slots_.end() ? nullptr : it->second.datum;
  }
  // The first key that exists, marked as mapped into the profile.
  const MachineDatum* take(std::initializer_list<std::string> keys) {
    for (const std::string& key : keys) {
      auto it = slots_.find(key);
      if (it != slots_.end() && std::holds_alternative<double>(it->second.datum->value)) {
        it->second.used = true;
        return it->second.datum;
      }
    }
    return nullptr;
  }
  std::optional<double> number_of(const std::string& key) const {
    const MachineDatum* d = peek(key);
    if (!d) return std::nullopt;
    if (auto* v = std::get_if<double>(&d->value)) return *v;
    return std::nullopt;
  }
  std::optional<std::string> text_of(const std::string& key) const {
    const MachineDatum* d = peek(key);
    if (!d) return std::nullopt;
    if (auto* v = std::get_if<std::string>(&d->value)) return *v;
    return std::nullopt;
  }

  static std::string written_name(const MachineDatum& d) {
    std::string s = d.full_name();
    if (!d.index.empty()) {
      s += '[';
      for (size_t i = 0; i < d.index.size(); ++i) s += (i ? "," : "") + d.index[i];
      s += ']';
    }
    return s;
  }

  // Sets `field` from the first datum found (value × factor) and records its source; else keeps
  // the field's default and lists it as missing. Returns whether it was found.
  bool map_value(const std::string& key, std::initializer_list<std::string> md_keys, double factor, double& field,
                 const std::string& what, const std::string& default_text) {
    if (const MachineDatum* d = take(md_keys)) {
      field = std::get<double>(d->value) * factor;
      out_.sources[key] = {written_name(*d), d->location()};
      return true;
    }
    out_.sources[key] = {"", "default"};
    out_.missing.push_back(what + " (" + key + "): not in the files, default " + default_text + " taken");
    return false;
  }
  bool map_int(const std::string& key, std::initializer_list<std::string> md_keys, int& field,
               const std::string& what) {
    double v = field;
    const bool found = map_value(key, md_keys, 1.0, v, what, std::to_string(field));
    field = to_int(v);
    return found;
  }

  // --- axes -----------------------------------------------------------------------------------

  void read_configuration() {
    for (size_t g = 0; g < 3; ++g) {
      const std::string idx = "[" + std::to_string(g) + "]";
      geo_channel_axis_[g] = to_int(number_of("$MC_AXCONF_GEOAX_ASSIGN_TAB" + idx).value_or(g + 1.0));
      const auto name = text_of("$MC_AXCONF_GEOAX_NAME_TAB" + idx);
      if (name && *name != kGeometry[g])
        out_.notes.push_back("geometry axis " + std::to_string(g + 1) + " is named '" + *name +
                             "' on the control; the profile calls it " + kGeometry[g]);
    }
    for (int c = 1; c <= 20; ++c)
      if (auto m = number_of("$MC_AXCONF_MACHAX_USED[" + std::to_string(c - 1) + "]"))
        channel_machine_axis_[c] = to_int(*m);
    if (channel_machine_axis_.empty()) {
      out_.missing.push_back(
          "MD20070 $MC_AXCONF_MACHAX_USED: not in the files; channel axes 1, 2, 3 taken as machine axes 1, 2, 3");
      for (int c = 1; c <= 3; ++c) channel_machine_axis_[c] = c;
    }
    master_spindle_ = to_int(number_of("$MC_SPIND_DEF_MASTER_SPIND").value_or(1.0));
    for (int axis : axes_seen_)
      if (number_of("$MA_SPIND_ASSIGN_TO_MACHAX[#" + std::to_string(axis) + "]").value_or(0.0) != 0.0)
        spindle_axes_.insert(axis);
  }

  int machine_axis_of_channel_axis(int c) const {
    auto it = channel_machine_axis_.find(c);
    return it == channel_machine_axis_.end() ? c : it->second;
  }

  std::string axis_key(const char* md, int axis) const {
    return std::string("$MA_") + md + "[#" + std::to_string(axis) + "]";
  }
  std::string dyn_key(const char* md, int axis) const {
    return std::string("$MA_") + md + "[0,#" + std::to_string(axis) + "]";
  }

  void read_axis(int m, bool geometry, AxisData& a) {
    const std::string k = "axes." + a.name + ".";
    const std::string who = "axis " + a.name + " (machine axis AX" + std::to_string(m) + ")";
    if (const MachineDatum* d = take({axis_key("IS_ROT_AX", m)})) {
      const bool rotary = std::get<double>(d->value) != 0.0;
      if (rotary && geometry)
        out_.notes.push_back(
            who + ": MD30300 IS_ROT_AX = 1 on a geometry axis; drycut's X, Y, Z are linear, taken as linear");
      a.rotary = rotary && !geometry;
      out_.sources[k + "rotary"] = {written_name(*d), d->location()};
    }
    const AxisUnits& u = a.rotary ? kRotaryUnits : kLinearUnits;
    const std::string pos = a.rotary ? "deg" : "mm";
    const std::string vel = a.rotary ? "_deg_min" : "_mm_min";
    const std::string acc = a.rotary ? "_deg_s2" : "_m_s2";
    const std::string jrk = a.rotary ? "_deg_s3" : "_m_s3";
    // Fallbacks when a required value is missing: MD32000 and MD32300 factory values, and a jerk
    // of 1000 m/s³ (1000 deg/s² and 10^6 deg/s³ on a rotary axis); docs/machine-data-import.md.
    a.max_velocity_mm_s = 10000.0 / 60.0;  // 10000 mm/min or deg/min
    a.max_accel_mm_s2 = 1000.0;            // 1 m/s² or 1000 deg/s²
    a.max_jerk_mm_s3 = 1.0e6;              // 1000 m/s³ or 10^6 deg/s³
    map_value(k + "max_velocity" + vel, {axis_key("MAX_AX_VELO", m)}, u.velocity, a.max_velocity_mm_s,
              who + " MD32000 MAX_AX_VELO", a.rotary ? "27.78 rev/min (10000 deg/min)" : "10000 mm/min");
    map_value(k + "max_accel" + acc, {dyn_key("MAX_AX_ACCEL", m), axis_key("MAX_AX_ACCEL", m)}, u.accel,
              a.max_accel_mm_s2, who + " MD32300 MAX_AX_ACCEL", a.rotary ? "2.78 rev/s² (1000 deg/s²)" : "1 m/s²");
    map_value(k + "max_jerk" + jrk, {dyn_key("MAX_AX_JERK", m), axis_key("MAX_AX_JERK", m)}, u.jerk, a.max_jerk_mm_s3,
              who + " MD32431 MAX_AX_JERK", a.rotary ? "2778 rev/s³ (10^6 deg/s³)" : "1000 m/s³");
    a.transition_jerk_mm_s3 = a.max_jerk_mm_s3;
    map_value(k + "transition_jerk" + jrk, {dyn_key("PATH_TRANS_JERK_LIM", m), axis_key("PATH_TRANS_JERK_LIM", m)},
              u.jerk, a.transition_jerk_mm_s3, who + " MD32432 PATH_TRANS_JERK_LIM", "= MAX_AX_JERK");
    map_value(k + "pos_velocity" + vel, {axis_key("POS_AX_VELO", m)}, u.velocity, a.pos_velocity_mm_s,
              who + " MD32060 POS_AX_VELO", a.rotary ? "10000 deg/min" : "10000 mm/min");
    map_value(k + "min_" + pos, {axis_key("POS_LIMIT_MINUS", m)}, 1.0, a.min_mm, who + " MD36100 POS_LIMIT_MINUS",
              "-1e9 (no limit)");
    map_value(k + "max_" + pos, {axis_key("POS_LIMIT_PLUS", m)}, 1.0, a.max_mm, who + " MD36110 POS_LIMIT_PLUS",
              "1e9 (no limit)");
    map_value(k + "compress_pos_tol_" + pos, {axis_key("COMPRESS_POS_TOL", m)}, 1.0, a.compress_pos_tol_mm,
              who + " MD33100 COMPRESS_POS_TOL", "0.1");
    if (a.rotary) read_rotary(m, k, a);
  }

  void read_rotary(int m, const std::string& k, AxisData& a) {
    if (const MachineDatum* d = take({axis_key("ROT_IS_MODULO", m)})) {
      a.modulo = std::get<double>(d->value) != 0.0;
      out_.sources[k + "modulo"] = {written_name(*d), d->location()};
    }
    if (a.modulo)
      map_value(k + "modulo_range_deg", {axis_key("MODULO_RANGE", m)}, 1.0, a.modulo_range,
                "axis " + a.name + " MD30330 MODULO_RANGE", "360 deg");
    if (const MachineDatum* d = take({axis_key("MISC_FUNCTION_MASK", m)})) {
      a.misc_function_mask = to_int(std::get<double>(d->value));
      out_.sources[k + "misc_function_mask"] = {written_name(*d), d->location()};
    }
  }

  void read_extra_axes() {
    for (const auto& [c, m] : channel_machine_axis_) {
      if (m == 0 || std::find(geo_channel_axis_.begin(), geo_channel_axis_.end(), c) != geo_channel_axis_.end())
        continue;
      if (spindle_axes_.count(m)) continue;  // a spindle, not a path or positioning axis
      std::string name;
      if (auto n = text_of("$MC_AXCONF_CHANAX_NAME_TAB[" + std::to_string(c - 1) + "]")) {
        name = upper_text(*n);
      } else if (static_cast<size_t>(c) <= kDefaultChannelAxisNames.size()) {
        name = kDefaultChannelAxisNames[c - 1];
        out_.missing.push_back("MD20080 $MC_AXCONF_CHANAX_NAME_TAB[" + std::to_string(c - 1) +
                               "]: not in the files, default name " + name);
      } else {
        out_.notes.push_back("channel axis " + std::to_string(c) + " has no name; not imported");
        continue;
      }
      AxisData a;
      a.name = name;
      read_axis(m, false, a);
      out_.profile.extra_axes.push_back(a);
    }
    std::sort(out_.profile.extra_axes.begin(), out_.profile.extra_axes.end(),
              [](const AxisData& x, const AxisData& y) { return x.name < y.name; });
  }

  // Per-axis data the profile holds once: the smallest over X, Y, Z (the tightest limit binds).
  void geometry_factor(const char* md, const std::string& key, const std::string& what, double& field) {
    std::optional<double> smallest;
    const MachineDatum* from = nullptr;
    bool differ = false;
    for (int g : geo_channel_axis_) {
      const MachineDatum* d =
          take({dyn_key(md, machine_axis_of_channel_axis(g)), axis_key(md, machine_axis_of_channel_axis(g))});
      if (!d) continue;
      const double v = std::get<double>(d->value);
      if (smallest && v != *smallest) differ = true;
      if (!smallest || v < *smallest) smallest = v, from = d;
    }
    if (!smallest) {
      out_.sources[key] = {"", "default"};
      out_.missing.push_back(what + " (" + key + "): not in the files, default " + format_number(field) + " taken");
      return;
    }
    field = *smallest;
    out_.sources[key] = {written_name(*from), from->location()};
    if (differ)
      out_.notes.push_back(what + " differs between X, Y, Z; the smallest, " + format_number(field) + ", is taken");
  }

  void read_geometry_axis_factors() {
    MachineProfile& p = out_.profile;
    geometry_factor("MAX_ACCEL_OVL_FACTOR", "path.max_accel_ovl_factor", "MD32310 MAX_ACCEL_OVL_FACTOR",
                    p.max_accel_ovl_factor);
    geometry_factor("SOFT_ACCEL_FACTOR", "path.soft_accel_factor", "MD32433 SOFT_ACCEL_FACTOR", p.soft_accel_factor);
    geometry_factor("G00_ACCEL_FACTOR", "path.g0_accel_factor", "MD32434 G00_ACCEL_FACTOR", p.g0_accel_factor);
    geometry_factor("G00_JERK_FACTOR", "path.g0_jerk_factor", "MD32435 G00_JERK_FACTOR", p.g0_jerk_factor);
  }

  // The elements 1..5 of the dynamic data (DYNPOS ... DYNPREC; machine/dynamic_groups.hpp) as
  // factors on element 0: per axis datum the smallest ratio over X, Y, Z (the tightest binds).
  void read_dynamic_group_factors() {
    struct Source {
      const char* md;
      const char* key;
      double DynamicGroupFactors::*field;
      bool channel;
    };
    static constexpr std::array<Source, 4> kSources{{
        {"MAX_AX_ACCEL", "max_ax_accel_factor", &DynamicGroupFactors::max_ax_accel, false},
        {"MAX_AX_JERK", "max_ax_jerk_factor", &DynamicGroupFactors::max_ax_jerk, false},
        {"PATH_TRANS_JERK_LIM", "path_trans_jerk_lim_factor", &DynamicGroupFactors::path_trans_jerk_lim, false},
        {"MAX_PATH_JERK", "max_path_jerk_factor", &DynamicGroupFactors::max_path_jerk, true},
    }};
    for (size_t g = 1; g < kDynamicGroupCount; ++g) {
      const std::string group(dynamic_group_name(static_cast<DynamicGroup>(g)));
      for (const Source& src : kSources) {
        std::optional<double> smallest;
        const MachineDatum* from = nullptr;
        auto consider = [&](const std::string& base_key, const std::string& group_key) {
          const auto base = number_of(base_key);
          const MachineDatum* d = take({group_key});
          if (!d || !base || *base <= 0) return;
          const double ratio = std::get<double>(d->value) / *base;
          if (!smallest || ratio < *smallest) smallest = ratio, from = d;
        };
        if (src.channel) {
          consider(std::string("$MC_") + src.md + "[0]", std::string("$MC_") + src.md + "[" + std::to_string(g) + "]");
        } else {
          for (int c : geo_channel_axis_) {
            const std::string m = "#" + std::to_string(machine_axis_of_channel_axis(c));
            consider(std::string("$MA_") + src.md + "[0," + m + "]",
                     std::string("$MA_") + src.md + "[" + std::to_string(g) + "," + m + "]");
          }
        }
        if (!smallest || *smallest <= 0) continue;  // absent: the factor stays 1, as the factory values
        out_.profile.dynamic_groups[g].*src.field = *smallest;
        out_.sources["dynamic_groups." + group + "." + src.key] = {written_name(*from), from->location()};
      }
    }
  }

  void read_ipo_cycle() {
    MachineProfile& p = out_.profile;
    const MachineDatum* sys = take({"$MN_SYSCLOCK_CYCLE_TIME"});
    const MachineDatum* ratio = take({"$MN_IPO_SYSCLOCK_TIME_RATIO"});
    if (sys && ratio) {
      p.ipo_cycle_s = std::get<double>(sys->value) * std::get<double>(ratio->value);
      out_.sources["path.ipo_cycle_ms"] = {written_name(*sys) + " × " + written_name(*ratio),
                                           sys->location() + ", " + ratio->location()};
      return;
    }
    out_.sources["path.ipo_cycle_ms"] = {"", "default"};
    out_.missing.push_back(std::string("IPO cycle (path.ipo_cycle_ms): ") +
                           (sys ? "" : "MD10050 SYSCLOCK_CYCLE_TIME ") +
                           (ratio ? "" : "MD10070 IPO_SYSCLOCK_TIME_RATIO ") + "not in the files, default 4 ms taken");
  }

  void read_nc_and_channel() {
    MachineProfile& p = out_.profile;
    read_ipo_cycle();
    double metric = 1;
    map_value("program.base_unit", {"$MN_SCALING_SYSTEM_IS_METRIC"}, 1.0, metric, "MD10240 SCALING_SYSTEM_IS_METRIC",
              "1 (mm)");
    p.base_unit_inch = metric == 0.0;
    double jerk = -1;
    if (map_value("path.max_path_jerk_m_s3", {"$MC_MAX_PATH_JERK[0]", "$MC_MAX_PATH_JERK"}, 1000.0, jerk,
                  "MD20600 MAX_PATH_JERK", "the smallest axis jerk"))
      p.path_jerk_mm_s3 = jerk;
    else
      p.path_jerk_mm_s3 = std::min({p.axes[0].max_jerk_mm_s3, p.axes[1].max_jerk_mm_s3, p.axes[2].max_jerk_mm_s3});
    map_value("path.curv_effect_on_path_accel", {"$MC_CURV_EFFECT_ON_PATH_ACCEL[0]", "$MC_CURV_EFFECT_ON_PATH_ACCEL"},
              1.0, p.curv_effect_on_path_accel, "MD20602 CURV_EFFECT_ON_PATH_ACCEL",
              format_number(p.curv_effect_on_path_accel));
    map_value("program.circle_error_const_mm", {"$MC_CIRCLE_ERROR_CONST", "$MN_CIRCLE_ERROR_CONST"}, 1.0,
              p.circle_error_const_mm, "MD21000 CIRCLE_ERROR_CONST", "0.01 mm");
    map_value("program.circle_error_factor", {"$MC_CIRCLE_ERROR_FACTOR", "$MN_CIRCLE_ERROR_FACTOR"}, 1.0,
              p.circle_error_factor, "MD21010 CIRCLE_ERROR_FACTOR", "0.001");
    map_value("program.cutcom_decel_limit", {"$SC_CUTCOM_DECEL_LIMIT"}, 1.0, p.cutcom_decel_limit,
              "SD42528 CUTCOM_DECEL_LIMIT", "0");
    map_value("program.cutcom_corner_limit_deg", {"$MC_CUTCOM_CORNER_LIMIT"}, 1.0, p.cutcom_corner_limit_deg,
              "MD20210 CUTCOM_CORNER_LIMIT", "100 deg");
    map_value("program.cutcom_curve_insert_limit_deg", {"$MC_CUTCOM_CURVE_INSERT_LIMIT"}, 1.0,
              p.cutcom_curve_insert_limit_deg, "MD20230 CUTCOM_CURVE_INSERT_LIMIT", "10 deg");
    map_int("program.cubic_spline_blocks", {"$MC_CUBIC_SPLINE_BLOCKS"}, p.cubic_spline_blocks,
            "MD20160 CUBIC_SPLINE_BLOCKS");
    // The NC block compressor (docs/compressor.md).
    CompressorData& c = p.compressor;
    map_value("compressor.compress_block_path_limit_mm", {"$MC_COMPRESS_BLOCK_PATH_LIMIT"}, 1.0,
              c.block_path_limit_mm, "MD20170 COMPRESS_BLOCK_PATH_LIMIT", "20 mm");
    map_value("compressor.compress_velo_tol_mm_min", {"$MC_COMPRESS_VELO_TOL"}, 1.0 / 60.0, c.velo_tol_mm_s,
              "MD20172 COMPRESS_VELO_TOL", "100 mm/min");
    map_int("compressor.compressor_mode", {"$MC_COMPRESSOR_MODE"}, c.mode, "MD20482 COMPRESSOR_MODE");
    map_value("compressor.compress_contur_tol_mm", {"$SC_COMPRESS_CONTUR_TOL"}, 1.0, c.contur_tol_mm,
              "SD42475 COMPRESS_CONTUR_TOL", "0.05 mm");
    map_value("compressor.crit_spline_angle_deg", {"$SC_CRIT_SPLINE_ANGLE"}, 1.0, c.crit_spline_angle_deg,
              "SD42470 CRIT_SPLINE_ANGLE", "36 deg");
    // Corner smoothing (docs/smoothing.md).
    SmoothingData& sm = p.smoothing;
    map_int("smoothing.smoothing_mode", {"$MC_SMOOTHING_MODE"}, sm.mode, "MD20480 SMOOTHING_MODE");
    map_value("smoothing.smooth_contur_tol_mm", {"$SC_SMOOTH_CONTUR_TOL"}, 1.0, sm.contur_tol_mm,
              "SD42465 SMOOTH_CONTUR_TOL", "0.05 mm");
    map_value("smoothing.g0_tolerance_factor", {"$MC_G0_TOLERANCE_FACTOR"}, 1.0, sm.g0_tolerance_factor,
              "MD20560 G0_TOLERANCE_FACTOR", "3");
    int ignore_ovl = sm.ignore_ovl_factor ? 1 : 0;
    map_int("smoothing.ignore_ovl_factor_for_adis", {"$MC_IGNORE_OVL_FACTOR_FOR_ADIS"}, ignore_ovl,
            "MD20490 IGNORE_OVL_FACTOR_FOR_ADIS");
    sm.ignore_ovl_factor = ignore_ovl != 0;
    map_value("smoothing.smooth_ori_tol_deg", {"$SC_SMOOTH_ORI_TOL"}, 1.0, sm.ori_tol_deg, "SD42466 SMOOTH_ORI_TOL",
              "0.05 deg");
    map_int("smoothing.mm_max_axispoly_per_block", {"$MC_MM_MAX_AXISPOLY_PER_BLOCK"}, sm.max_axispoly_per_block,
            "MD28520 MM_MAX_AXISPOLY_PER_BLOCK");
    map_int("program.cutcom_maxnum_check_blocks", {"$MC_CUTCOM_MAXNUM_CHECK_BLOCKS"}, p.cutcom_maxnum_check_blocks,
            "MD20240 CUTCOM_MAXNUM_CHECK_BLOCKS");
    map_int("program.cutcom_maxnum_dummy_blocks", {"$MC_CUTCOM_MAXNUM_DUMMY_BLOCKS"}, p.cutcom_maxnum_dummy_blocks,
            "MD20250 CUTCOM_MAXNUM_DUMMY_BLOCKS");
    map_int("program.tool_change_mode", {"$MC_TOOL_CHANGE_MODE"}, p.tool_change_mode, "MD22550 TOOL_CHANGE_MODE");
    map_int("program.tool_change_m_code", {"$MC_TOOL_CHANGE_M_CODE"}, p.tool_change_m_code,
            "MD22560 TOOL_CHANGE_M_CODE");
    map_int("program.cutting_edge_default", {"$MC_CUTTING_EDGE_DEFAULT"}, p.cutting_edge_default,
            "MD20270 CUTTING_EDGE_DEFAULT");
  }

  // The master spindle's speed limit and accelerations (gear stage 1 where the datum has stages).
  void read_spindle() {
    MachineProfile& p = out_.profile;
    p.master_spindle = master_spindle_;
    int m = 0;
    for (int axis : spindle_axes_)
      if (number_of("$MA_SPIND_ASSIGN_TO_MACHAX[#" + std::to_string(axis) + "]") == master_spindle_) m = axis;
    const std::string s = "#" + std::to_string(m);
    const std::string who =
        m ? "spindle " + std::to_string(master_spindle_) + " (machine axis AX" + std::to_string(m) + ")"
          : "master spindle (no axis with MD35000 SPIND_ASSIGN_TO_MACHAX)";
    map_value("path.max_spindle_speed_rpm", {"$MA_SPIND_VELO_LIMIT[" + s + "]"}, 1.0, p.max_spindle_speed_rpm,
              who + " MD35100 SPIND_VELO_LIMIT", "10000 rev/min");
    map_value("path.spindle_posctrl_velo_rpm", {"$MA_SPIND_POSCTRL_VELO[" + s + "]"}, 1.0, p.spindle_posctrl_velo_rpm,
              who + " MD35300 SPIND_POSCTRL_VELO", "500 rev/min");
    map_value("path.spindle_speedctrl_accel_rev_s2",
              {"$MA_GEAR_STEP_SPEEDCTRL_ACCEL[1," + s + "]", "$MA_GEAR_STEP_SPEEDCTRL_ACCEL[0," + s + "]",
               "$MA_GEAR_STEP_SPEEDCTRL_ACCEL[" + s + "]"},
              1.0, p.spindle_speedctrl_accel_rev_s2, who + " MD35200 GEAR_STEP_SPEEDCTRL_ACCEL", "30 rev/s²");
    map_value("path.spindle_posctrl_accel_rev_s2",
              {"$MA_GEAR_STEP_POSCTRL_ACCEL[1," + s + "]", "$MA_GEAR_STEP_POSCTRL_ACCEL[0," + s + "]",
               "$MA_GEAR_STEP_POSCTRL_ACCEL[" + s + "]"},
              1.0, p.spindle_posctrl_accel_rev_s2, who + " MD35210 GEAR_STEP_POSCTRL_ACCEL", "30 rev/s²");
    map_value("path.spindle_des_velo_tol", {"$MA_SPIND_DES_VELO_TOL[" + s + "]"}, 1.0, p.spindle_des_velo_tol,
              who + " MD35150 SPIND_DES_VELO_TOL", "0.1");
    map_int("path.spindle_on_speed_at_ipo_start", {"$MA_SPIND_ON_SPEED_AT_IPO_START[" + s + "]"},
            p.spindle_on_speed_at_ipo_start, who + " MD35500 SPIND_ON_SPEED_AT_IPO_START");
  }

  // MD20150 holds an index per G group; drycut does not translate the indices (yet) and starts
  // from the standard reset table of the machine data list instead (docs/machine-profile.md).
  void read_reset_gcodes() {
    out_.profile.reset_gcodes = {"G1",    "G17",  "G40",  "G500", "G60",  "G71",  "G90", "G94",
                                 "BRISK", "BNAT", "ENAT", "NORM", "G450", "CDOF", "CFC", "FNORM"};
    out_.sources["program.reset_gcodes"] = {"", "default"};
    out_.missing.push_back(
        "MD20150 GCODE_RESET_VALUES (program.reset_gcodes): not translated from the files, the standard table "
        "G1 G17 G40 G500 G60 G71 G90 G94 BRISK BNAT ENAT NORM G450 CDOF CFC FNORM taken");
  }

  // Settable frames as the data backup writes them, one component per line: $P_UIFR[n,X,TR]
  // (translation), FI (fine offset, added), RT (rotation, degrees). n = 1..4 is G54..G57,
  // n = 5..99 G505..G599 (n = 0, G500, and scale/mirror components stay in machine_data).
  void read_settable_frames() {
    MachineProfile& p = out_.profile;
    for (int n = 1; n <= 99; ++n) {
      const std::string name =
          n <= 4 ? "G5" + std::to_string(n + 3) : "G5" + std::string(n < 10 ? "0" : "") + std::to_string(n);
      const std::string key = "$P_UIFR[" + std::to_string(n) + ",";
      Eigen::Vector3d offset = Eigen::Vector3d::Zero(), rotation = Eigen::Vector3d::Zero();
      bool has_offset = false, has_rotation = false;
      for (int g = 0; g < 3; ++g) {
        const std::string axis = std::string(kGeometry[g]) + ",";
        for (const char* component : {"TR", "FI"})
          if (const MachineDatum* d = take({key + axis + component + "]"})) {
            offset[g] += std::get<double>(d->value);
            has_offset = true;
            out_.sources["program.work_offsets_mm." + name] = {written_name(*d), d->location()};
          }
        if (const MachineDatum* d = take({key + axis + "RT]"})) {
          rotation[g] = std::get<double>(d->value);
          has_rotation = true;
          out_.sources["program.work_offset_rotations_deg." + name] = {written_name(*d), d->location()};
        }
      }
      if (has_offset) p.work_offsets[name] = offset;
      if (has_rotation) p.work_offset_rotations_deg[name] = rotation;
    }
  }

  // Tool offsets as the tool data backup writes them: $TC_DP3/4/5[t,d] lengths 1..3 and
  // $TC_DP6[t,d] radius of edge d of tool t, each plus its wear value ($TC_DP12/13/14, $TC_DP15),
  // which the control adds; $TC_DP21..23 the base lengths; $TC_DP1 the tool type, $TC_DP2 the
  // cutting edge position; $TC_DPNT[t,d] the number of teeth (tooth feed G95 FZ); $TC_TP2[t] the
  // tool's name (else its number). Edges 1..12 as the profile takes them.
  void read_tools() {
    struct Edge {
      double length = 0, radius = 0, length2 = 0, length3 = 0;
      std::array<double, 3> base{0.0, 0.0, 0.0};
      int teeth = 0, type = 0, position = 0;
      const MachineDatum *length_from = nullptr, *radius_from = nullptr;
    };
    std::map<int, std::map<int, Edge>> tools;
    for (auto& [key, slot] : slots_) {
      const MachineDatum& d = *slot.datum;
      const double* v = std::get_if<double>(&d.value);
      if (d.area != "TC" || !v || d.index.size() != 2 || !all_digits(d.index[0]) || !all_digits(d.index[1])) continue;
      const bool length = d.name == "DP3" || d.name == "DP12", radius = d.name == "DP6" || d.name == "DP15";
      const bool teeth = d.name == "DPNT" && *v >= 0 && *v <= 32000 && *v == std::floor(*v);
      // $TC_DP1 the tool type, $TC_DP2 the edge position, lengths 2 and 3 with their wear, the
      // base lengths.
      const bool type = d.name == "DP1" && *v >= 0 && *v <= 999 && *v == std::floor(*v);
      const bool position = d.name == "DP2" && *v >= 0 && *v <= 9 && *v == std::floor(*v);
      const bool length2 = d.name == "DP4" || d.name == "DP13", length3 = d.name == "DP5" || d.name == "DP14";
      const int base = d.name == "DP21" ? 0 : d.name == "DP22" ? 1 : d.name == "DP23" ? 2 : -1;
      const bool other = type || position || length2 || length3 || base >= 0;
      const int t = std::stoi(d.index[0]), e = std::stoi(d.index[1]);
      if ((!length && !radius && !teeth && !other) || t > 32000 || e < 1 || e > 12) continue;
      Edge& edge = tools[t][e];
      if (teeth)
        edge.teeth = static_cast<int>(*v);
      else if (type)
        edge.type = static_cast<int>(*v);
      else if (position)
        edge.position = static_cast<int>(*v);
      else if (length2)
        edge.length2 += *v;
      else if (length3)
        edge.length3 += *v;
      else if (base >= 0)
        edge.base[static_cast<size_t>(base)] = *v;
      else
        (length ? edge.length : edge.radius) += *v;
      if (d.name == "DP3") edge.length_from = &d;
      if (d.name == "DP6") edge.radius_from = &d;
      // These stay readable as machine data too ($TC_DP1 in a tool macro).
      if (!other) slot.used = true;
    }
    std::set<std::string> names;  // name and duplo number
    for (const auto& [t, edges] : tools) {
      Tool tool;
      tool.number = t;
      const std::string tool_key = "tools[" + std::to_string(out_.profile.tools.size()) + "].";
      tool.name = text_of("$TC_TP2[" + std::to_string(t) + "]").value_or(std::to_string(t));
      if (const MachineDatum* n = peek("$TC_TP2[" + std::to_string(t) + "]"))
        out_.sources[tool_key + "name"] = {written_name(*n), n->location()};
      // $TC_TP1[t]: the duplo number of sister tools (same name); without it each name once.
      if (const auto duplo = number_of("$TC_TP1[" + std::to_string(t) + "]"); duplo && *duplo >= 1 && *duplo <= 32000) {
        tool.duplo = static_cast<int>(*duplo);
        if (const MachineDatum* d = peek("$TC_TP1[" + std::to_string(t) + "]"))
          out_.sources[tool_key + "duplo"] = {written_name(*d), d->location()};
      }
      if (!names.insert(tool.name + '\n' + std::to_string(tool.duplo)).second) {
        out_.notes.push_back("tool " + std::to_string(t) + ": name '" + tool.name + "' used twice, named '" +
                             tool.name + "_T" + std::to_string(t) + "' in the profile");
        tool.name += "_T" + std::to_string(t);
      }
      const std::string k = tool_key + "edges[";
      for (const auto& [d, edge] : edges) {
        const std::string e = k + std::to_string(tool.edges.size()) + "].";
        if (edge.length_from)
          out_.sources[e + "length_mm"] = {written_name(*edge.length_from), edge.length_from->location()};
        if (edge.radius_from)
          out_.sources[e + "radius_mm"] = {written_name(*edge.radius_from), edge.radius_from->location()};
        if (const MachineDatum* from = edge.length_from ? edge.length_from : edge.radius_from) {
          out_.sources[e + "d"] = {written_name(*from), from->location()};
          out_.sources[tool_key + "number"] = {written_name(*from), from->location()};
        }
        ToolEdge te{d, edge.radius, edge.length, edge.teeth};
        te.type = edge.type;
        te.length2_mm = edge.length2;
        te.length3_mm = edge.length3;
        te.base_mm = edge.base;
        te.edge_position = edge.position;
        tool.edges.push_back(te);
      }
      out_.profile.tools.push_back(tool);
    }
  }

  // MD20100 DIAMETER_AX_DEF: the control's name of the transverse geometry axis ("" none).
  void read_transverse_axis() {
    const MachineDatum* d = peek("$MC_DIAMETER_AX_DEF");
    const std::string* name = d ? std::get_if<std::string>(&d->value) : nullptr;
    if (!name || name->empty()) return;
    for (size_t g = 0; g < 3; ++g) {
      const std::string control_name = text_of("$MC_AXCONF_GEOAX_NAME_TAB[" + std::to_string(g) + "]").value_or(kGeometry[g]);
      if (upper_text(control_name) != upper_text(*name)) continue;
      out_.profile.diameter_axis = kGeometry[g];
      out_.sources["program.diameter_ax_def"] = {written_name(*d), d->location()};
      return;
    }
    out_.notes.push_back(written_name(*d) + " = \"" + *name + "\": not a geometry axis, no transverse axis imported");
  }

  // $TC_CARR23 of the first tool carrier: T the tool turns (a head), P the part (a table); PGA
  // "Toolholder data", Commissioning Manual IM9 21.7 (M, mixed, is not modelled).
  void read_swivel_kinematics() {
    for (int n = 1; n <= 99; ++n) {
      const MachineDatum* d = peek("$TC_CARR23[" + std::to_string(n) + "]");
      const std::string* kind = d ? std::get_if<std::string>(&d->value) : nullptr;
      if (!kind) continue;
      const std::string k = upper_text(*kind);
      if (k == "T" || k == "P") {
        out_.profile.swivel_kinematics = k == "P" ? "table" : "head";
        out_.sources["program.swivel_kinematics"] = {written_name(*d), d->location()};
      } else {
        out_.notes.push_back(written_name(*d) + " = \"" + *kind +
                             "\": kinematic type not modelled, swivel data not imported");
      }
      return;
    }
  }

  // --- the rest -------------------------------------------------------------------------------

  void keep_the_rest() {
    int texts = 0;
    for (const auto& [key, slot] : slots_) {
      if (slot.used) continue;
      const MachineDatum& d = *slot.datum;
      const double* v = std::get_if<double>(&d.value);
      if (!v) {
        ++texts;
        continue;
      }
      std::string name = d.full_name();
      if (!d.index.empty()) {
        name += '[';
        for (size_t i = 0; i < d.index.size(); ++i) {
          const int axis = is_axis_area(d.area) ? axis_number(d.index[i]) : 0;
          auto it = machine_axis_names_.find(axis);
          name += (i ? "," : "") + (axis > 0 && it != machine_axis_names_.end() ? it->second : d.index[i]);
        }
        name += ']';
      }
      out_.profile.machine_data[name] = *v;
      out_.sources["machine_data." + name] = {written_name(d), d.location()};
      ++out_.kept;
    }
    if (texts)
      out_.notes.push_back(
          std::to_string(texts) +
          " text data (axis names and the like) used for the axis set-up only; machine_data holds numbers");
  }

  MachineDataImport& out_;
  std::map<std::string, Slot> slots_;              // "$MA_MAX_AX_VELO[0,#3]" -> datum
  std::map<int, std::string> machine_axis_names_;  // machine axis number -> MD10000 name
  std::set<int> axes_seen_;
  std::map<int, int> channel_machine_axis_;       // channel axis -> machine axis (MD20070)
  std::array<int, 3> geo_channel_axis_{1, 2, 3};  // geometry axis -> channel axis (MD20050)
  std::set<int> spindle_axes_;
  int master_spindle_ = 1;
};

// Every key of the canonical profile that the import did not set comes from drycut's defaults.
void complete_sources(MachineDataImport& r) {
  for (const auto& [key, value] : flatten_profile_json(profile_to_json(r.profile))) {
    (void)value;
    if (key == "name" || key.starts_with("machine_data.")) continue;
    r.sources.try_emplace(key, ValueSource{"", "default"});
  }
}

}  // namespace

MachineDataImport import_machine_data(const MachineDataText& text, const std::string& profile_name) {
  MachineDataImport result;
  result.profile.name = profile_name;
  Importer(text, result).run();
  // Validate as any profile file is validated (ranges, limits), and keep the canonical form.
  result.profile = load_profile_json(profile_to_json(result.profile), "<imported machine data>");
  complete_sources(result);
  return result;
}

std::string sources_to_json(const MachineDataImport& r) {
  nlohmann::json root;
  nlohmann::json values = nlohmann::json::object();
  for (const auto& [key, s] : r.sources) values[key] = {{"datum", s.datum}, {"origin", s.origin}};
  root["sources"] = values;
  root["missing"] = r.missing;
  root["notes"] = r.notes;
  return root.dump(2);
}

std::map<std::string, ValueSource> load_sources_json(const std::string& json_text, std::vector<std::string>* missing) {
  std::map<std::string, ValueSource> out;
  const nlohmann::json root = nlohmann::json::parse(json_text, nullptr, false);
  if (!root.is_object() || !root.contains("sources") || !root["sources"].is_object()) return out;
  if (missing && root.contains("missing") && root["missing"].is_array())
    for (const auto& m : root["missing"])
      if (m.is_string()) missing->push_back(m.get<std::string>());
  for (auto it = root["sources"].begin(); it != root["sources"].end(); ++it) {
    const auto& v = it.value();
    if (v.is_object() && v.value("origin", nlohmann::json()).is_string())
      out[it.key()] = {v.value("datum", std::string()), v.value("origin", std::string())};
  }
  return out;
}

}  // namespace drycut::machine
