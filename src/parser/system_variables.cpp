#include "parser/system_variables.hpp"

#include "parser/run_clock.hpp"

#include <array>

#include "parser/expression_evaluator.hpp"

namespace drycut::parser {
namespace {

bool starts_with(std::string_view s, std::string_view p) { return s.substr(0, p.size()) == p; }

constexpr std::array<std::string_view, 8> kIoPrefixes{"$A_IN", "$A_OUT", "$A_INA", "$A_OUTA",
                                                       "$A_DBB", "$A_DBW", "$A_DBD", "$A_DBR"};

}  // namespace

SystemVariableClass classify_system_variable(std::string_view n) {
  if (starts_with(n, "$MN_") || starts_with(n, "$MC_") || starts_with(n, "$MA_") || starts_with(n, "$MM_"))
    return SystemVariableClass::MachineData;
  if (starts_with(n, "$SN_") || starts_with(n, "$SC_") || starts_with(n, "$SA_"))
    return SystemVariableClass::SettingData;
  for (auto p : kIoPrefixes)
    if (n == p) return SystemVariableClass::InputOutput;
  if (starts_with(n, "$TC_")) return SystemVariableClass::ToolData;
  if (starts_with(n, "$P_") || starts_with(n, "$AA_") || starts_with(n, "$AC_") || starts_with(n, "$VA_") ||
      starts_with(n, "$A_") || starts_with(n, "$PI") || starts_with(n, "$R") || starts_with(n, "$DRYCUT_"))
    return SystemVariableClass::State;
  return SystemVariableClass::Unknown;
}

std::string_view system_variable_class_name(SystemVariableClass c) {
  switch (c) {
    case SystemVariableClass::MachineData: return "machine data";
    case SystemVariableClass::SettingData: return "setting data";
    case SystemVariableClass::State: return "controller state";
    case SystemVariableClass::InputOutput: return "input/output";
    case SystemVariableClass::ToolData: return "tool data";
    default: return "system variable";
  }
}

std::string system_variable_key(std::string_view upper_name, std::span<const Value> indices) {
  std::string key(upper_name);
  if (indices.empty()) return key;
  key += '[';
  for (size_t k = 0; k < indices.size(); ++k) {
    if (k) key += ',';
    key += as_text(indices[k]);
  }
  key += ']';
  return key;
}

// Why an actual position read the same again (the 990004 of a loop waiting for it).
constexpr std::string_view kAxisStands = "the axis stands there; the loop waits for a position it does not reach";

SystemVariables::ReadResult SystemVariables::read(std::string_view name, std::span<const Value> indices) const {
  const std::string key = system_variable_key(name, indices);
  if (name.size() > 1 && (name[1] == 'A' || name[1] == 'V')) ++main_run_reads_;
  // Markers and parameters of synchronized actions (Job Planning, "Synchronized actions":
  // $AC_MARKER, $AC_PARAM): the actions change them while the program polls them.
  const bool sync_action_variable = name == "$AC_MARKER" || name == "$AC_PARAM";
  if (sync_action_variable) note_external_read(key);
  else if (!sync_targets_.empty() && (sync_targets_.count(key) || sync_targets_.count(name)))
    note_external_read(key + " (written by a synchronized action)");
  if (name == "$AC_TIMER") {
    // Job Planning, "Timer variable $AC_TIMER[n]": counts seconds from the value written (>= 0)
    // until -1 stops it. Time is the interpreter's (poll_clock), so a timed warm-up loop ends.
    if (auto it = timer_start_.find(key); it != timer_start_.end())
      return {Value((view_ ? poll_clock() : 0.0) - it->second), false};
    if (auto it = written_.find(key); it != written_.end()) return {Value(it->second), false};
    return {Value(0.0), false};
  }
  if (auto it = texts_.find(key); it != texts_.end()) return {Value::of_text(it->second), false};
  if (auto it = written_.find(key); it != written_.end()) return {Value(it->second), false};
  if (sync_action_variable) return {Value(0.0), false};  // 0 until written
  if (name == "$AC_CUTTING_TIME") {
    // Tool action time: only motion at feed with a tool active counts, so polling it passes no
    // time (docs/controller-state.md "Clock, run-time counters ...").
    ++view_reads_;
    return {Value(view_ ? view_->cutting_time_s() : 0.0), false};
  }
  if (view_ && (name == "$AA_S" || view_->changes_while_polled(name, indices)))
    return read_process_value(name, indices, key);
  if (run_clock_reading(name, 0.0)) {
    ++view_reads_;  // state of the interpreter: a loop that polls the clock is not endless
    return {Value(*run_clock_reading(name, view_ ? poll_clock() : 0.0)), false};
  }
  // A measured value ($AA_MM[ax], $AA_MW[ax], $AA_MM1..4, $AA_MW1..4: Job Planning, "Measuring")
  // or whether the probe switched ($AC_MEA[n]): a dry run touches nothing, so what the program
  // decides from it is unknown (990021).
  if (name.starts_with("$AA_MM") || name.starts_with("$AA_MW") || name == "$AC_MEA") measurement_read_ = key;
  const SystemVariableClass c = classify_system_variable(name);
  if (c == SystemVariableClass::InputOutput) {
    ++input_reads_;
    last_input_ = key;
  }
  if (auto it = values_.find(key); it != values_.end()) return {Value(it->second), false};
  if (auto it = text_values_.find(key); it != text_values_.end()) return {Value::of_text(it->second), false};
  if (view_ && (c == SystemVariableClass::State || c == SystemVariableClass::ToolData)) {
    ++view_reads_;
    if (auto v = view_->read_system_variable(name, indices)) {
      // An axis standing where it stood at the last read tells the loop nothing new: a macro
      // waiting for a position the axis never reaches is the endless loop it is (990004).
      if (is_actual_position_name(name) && v->is_number()) note_process_value(key, *v, kAxisStands);
      return {*v, false};
    }
  }
  // A frame the program wrote and the interpreter does not keep reads back as written.
  if (auto it = frames_.find(key); it != frames_.end()) return {it->second, false};
  if (c == SystemVariableClass::InputOutput) return {Value(0.0), false};
  // The loader alone (no interpreter behind it) reads state as 0, silently.
  if (!view_ && (c == SystemVariableClass::State || c == SystemVariableClass::ToolData)) return {Value(0.0), false};
  return {Value(0.0), true};
}

SystemVariables::ReadResult SystemVariables::read_process_value(std::string_view name,
                                                               std::span<const Value> indices,
                                                               const std::string& key) const {
  // The actual speed follows its run-up ramp in time, an axis from POSA its way: a poll of them
  // lets the clock run, as a poll of the clock does (a warm-up loop waits for the speed, a
  // macro for the axis). Once it reads what it read at the
  // last poll the ramp is over and the speed stays until a block changes it: that read neither
  // reads changing state nor lets time count for the loop guard, so a loop waiting for a speed
  // the spindle never reaches (above MD35100, G26 or LIMS) is the endless loop it is on the
  // machine (alarm 990004 at once, not after 10^8 lines).
  poll_clock();
  ++process_reads_;
  ++view_reads_;
  const auto v = view_->read_system_variable(name, indices);
  if (!v) return {Value(0.0), true};
  const bool spindle = name == "$AA_S";
  if (!note_process_value(key, *v,
                          spindle ? "the spindle does not reach the speed the loop waits for; its limits are MD35100 "
                                    "max_spindle_speed_rpm, G26 and LIMS"
                                  : kAxisStands)) {
    --clock_reads_;
    --process_reads_;
  }
  return {*v, false};
}

bool SystemVariables::note_process_value(const std::string& key, const Value& v, std::string_view why) const {
  auto [last, first] = last_process_values_.try_emplace(key, v.number);
  const bool changed = first || last->second != v.number;
  if (!changed) {
    --view_reads_;
    settled_read_ = key + " stays at " + as_text(v) + ": " + std::string(why);
  }
  last->second = v.number;
  return changed;
}

void SystemVariables::write(std::string_view name, std::span<const Value> indices, const Value& v) {
  std::string key = system_variable_key(name, indices);
  if (name == "$AC_TIMER" && v.is_number()) {
    const double now = view_ ? view_->elapsed_s() : 0.0;
    if (v.number >= 0) {
      timer_start_[key] = now - v.number;
      written_.erase(key);
    } else if (auto it = timer_start_.find(key); it != timer_start_.end()) {
      written_[key] = now - it->second;  // stopped: it keeps the time it reached
      timer_start_.erase(it);
    }
    return;
  }
  if (v.kind == ValueKind::Frame) {
    // Frames go to the interpreter (Block::system_writes), which answers later reads of those it
    // keeps; a read must never see the frame as a text (alarm 12150 on `_FR=$P_PFRAME`).
    texts_.erase(key);
    written_.erase(key);
    // Components written before belong to the old frame ("$P_UIFR[1]" -> "$P_UIFR[1,X,TR]").
    const std::string components = key.back() == ']' ? key.substr(0, key.size() - 1) + "," : key + "[";
    for (auto it = written_.lower_bound(components); it != written_.end() && it->first.rfind(components, 0) == 0;)
      it = written_.erase(it);
    frames_[std::move(key)] = v;
    return;
  }
  if (v.is_number() && is_frame_variable_name(name)) {
    // A frame component ($P_IFRAME[X,TR]=50): the interpreter keeps the frame and answers later
    // reads; a copy here would outlive the next G54 .. that changes the frame.
    written_.erase(key);
    return;
  }
  if (v.is_number()) {
    texts_.erase(key);
    frames_.erase(key);
    written_[std::move(key)] = v.number;
  } else {
    written_.erase(key);
    texts_[std::move(key)] = v.text;
  }
}

void SystemVariables::append_state(std::string& out) const {
  // A running timer is part of the state: a loop that waits for it is not endless.
  for (const auto& [k, start] : timer_start_) {
    const double reading = (view_ ? view_->elapsed_s() : 0.0) - start;
    out += k;
    out.append(reinterpret_cast<const char*>(&reading), sizeof reading);
  }
  for (const auto& [k, v] : written_) {
    out += k;
    out.append(reinterpret_cast<const char*>(&v), sizeof v);
  }
  for (const auto& [k, v] : frames_) {
    out += k;
    out += v.text;
  }
  for (const auto& [k, v] : texts_) {
    out += k;
    out += '=';
    out += v;
    out += '\0';
  }
}

bool SystemVariables::is_known(std::string_view name) const {
  return classify_system_variable(name) != SystemVariableClass::Unknown;
}

bool SystemVariables::profile_gives(std::string_view name) const {
  if (values_.find(name) != values_.end() || text_values_.find(name) != text_values_.end()) return true;
  // Indexed data: the first key from "NAME[" on (keys like "NAMEX" sort before it).
  const std::string indexed = std::string(name) + '[';
  const auto hit = values_.lower_bound(indexed);
  const auto text_hit = text_values_.lower_bound(indexed);
  return (hit != values_.end() && hit->first.starts_with(indexed)) ||
         (text_hit != text_values_.end() && text_hit->first.starts_with(indexed));
}

bool SystemVariables::input_arrived(const std::string& key) {
  if (key.rfind("$A_IN[", 0) != 0) return false;
  double& v = values_[key];
  v = v == 0.0 ? 1.0 : 0.0;
  return true;
}

}  // namespace drycut::parser
