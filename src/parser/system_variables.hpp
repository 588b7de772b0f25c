#pragma once
// The one registry of `$` system variables (PGA Job Planning / "System variables" list manual).
// Each name falls into a class by its prefix, and the class says where its value comes from:
//
//   $MN_ $MC_ $MA_ $SN_ $SC_ $SA_   machine and setting data: the profile's `machine_data` map
//                                   (key as written, e.g. "$MA_COMPRESS_POS_TOL[X1]"); a name
//                                   the profile lacks reads 0 with one warning naming it
//   $P_ $AA_ $AC_ $VA_ $A_ (state)   programmed and actual state: asked of the controller view
//                                   (the interpreter in `run`; in a dry run actual = programmed);
//                                   the run clock and $AC_TIMER from its time (run_clock.hpp)
//   $A_IN $A_OUT $A_INA $A_OUTA $A_DBB $A_DBW $A_DBD $A_DBR   inputs, outputs, PLC data:
//                                   the profile's `machine_data` map, default 0 (documented)
//   $TC_                            tool data: written values, else the controller view
//   anything else                   0 with one warning naming it (never an alarm: the control
//                                   knows thousands of names, a false alarm is the worst bug)
//
// A write is kept (later reads see it) and handed to the interpreter with the block
// (Block::system_writes), which applies what it models (tool data, frames).
#include <map>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <string_view>

#include "parser/value.hpp"

namespace drycut::parser {

enum class SystemVariableClass : uint8_t { MachineData, SettingData, State, InputOutput, ToolData, Unknown };

SystemVariableClass classify_system_variable(std::string_view upper_name);
std::string_view system_variable_class_name(SystemVariableClass c);

// A frame variable of the $P_ family: every name ending in FRAME or FR ($P_PFRAME, $P_UIFR,
// $P_IFRAME, $P_BFRAME, $P_CHBFR ...; K2, "Frames").
inline bool is_frame_variable_name(std::string_view upper_name) {
  return upper_name.rfind("$P_", 0) == 0 && (upper_name.ends_with("FRAME") || upper_name.ends_with("FR"));
}

// The actual position of an axis: machine, basic and workpiece system, path or interpolator
// value ($AA_IM, $VA_IM, $AA_IB, $AA_IW, $VA_IW, $AA_IEN; Job Planning, "System variables").
inline bool is_actual_position_name(std::string_view n) {
  return n == "$AA_IM" || n == "$VA_IM" || n == "$AA_IB" || n == "$AA_IW" || n == "$VA_IW" || n == "$AA_IEN";
}

// "$MA_X" + [X1] -> "$MA_X[X1]": the key of machine data maps and written values.
std::string system_variable_key(std::string_view upper_name, std::span<const Value> indices);

// What the interpreter knows: programmed state, actual state (= programmed in a dry run), tools.
class ControllerStateView {
 public:
  virtual ~ControllerStateView() = default;
  virtual std::optional<Value> read_system_variable(std::string_view upper_name, std::span<const Value> indices) const = 0;
  // Seconds the program has run so far, as far as the interpreter knows.
  virtual double elapsed_s() const { return 0.0; }
  // The same, for a read of the run clock ($AC_TIMER, $AC_OPERATING_TIME, $A_SECOND ...) on
  // program line `line` (a running count of lines executed): such a read waits for the main
  // run, so a program that polls the clock lets time pass (Interpreter::poll_clock).
  virtual double poll_clock(uint64_t /*line*/) const { return elapsed_s(); }
  // Whether the actual value read changes with time as it is polled (an axis on its way from
  // POSA read by $AA_IM): such a read lets the clock run, as a read of $AA_S does.
  virtual bool changes_while_polled(std::string_view /*upper_name*/, std::span<const Value> /*indices*/) const {
    return false;
  }
  // Seconds of motion at feed with a tool active so far ($AC_CUTTING_TIME, tool action time).
  virtual double cutting_time_s() const { return 0.0; }
  // A component [axis, TR|FI|RT|SC|MI] of a FRAME value (its text, "CTRANS(X,10)"; empty: the
  // null frame), and the text of that frame with the component set: the loader keeps FRAME
  // variables as text and the interpreter computes frames. None where it cannot.
  virtual std::optional<double> frame_component(std::string_view /*frame_text*/, std::string_view /*axis*/,
                                                std::string_view /*component*/) const {
    return std::nullopt;
  }
  virtual std::optional<std::string> frame_with_component(std::string_view /*frame_text*/, std::string_view /*axis*/,
                                                          std::string_view /*component*/, double /*value*/) const {
    return std::nullopt;
  }
};

using MachineDataMap = std::map<std::string, double, std::less<>>;
using MachineDataTexts = std::map<std::string, std::string, std::less<>>;

class SystemVariables {
 public:
  explicit SystemVariables(MachineDataMap machine_data, MachineDataTexts machine_texts = {})
      : values_(std::move(machine_data)), text_values_(std::move(machine_texts)) {
    for (const auto& [key, value] : values_)
      if (classify_system_variable(std::string_view(key).substr(0, key.find('['))) == SystemVariableClass::InputOutput)
        given_signals_.insert(key);
  }
  void set_view(const ControllerStateView* view) { view_ = view; }
  // The loader executes its next line (the clock's reads on one line see one time).
  void begin_line() { ++line_; }

  struct ReadResult {
    Value value;
    bool assumed = false;  // not known: the documented default was used (warn once)
  };
  ReadResult read(std::string_view upper_name, std::span<const Value> indices) const;
  void write(std::string_view upper_name, std::span<const Value> indices, const Value& v);
  bool is_known(std::string_view upper_name) const;
  // The profile gives this datum, as a scalar or with an index ("$MC_X" or "$MC_X[...]").
  bool profile_gives(std::string_view upper_name) const;
  // The written values as bytes (the loop guard's state).
  void append_state(std::string& out) const;
  // How many values were read from the interpreter so far.
  uint64_t view_reads() const { return view_reads_; }
  // The interpreter's clock (0 without an interpreter).
  double elapsed_s() const { return view_ ? view_->elapsed_s() : 0.0; }
  // How many inputs and PLC data ($A_IN, $A_DBB ..., not written by the program) were read so
  // far, and the last one read ("$A_IN[3]"): a loop that repeats while reading them waits.
  uint64_t input_reads() const { return input_reads_; }
  // How many main-run variables ($A..., $V...: actual values, inputs, clocks) were read so far.
  // Reading one outside a synchronized action stops the block preparation until the blocks
  // before it have run (an implicit STOPRE; Job Planning, "Preprocessing stop (STOPRE)").
  uint64_t main_run_reads() const { return main_run_reads_; }
  // A user variable defined with SYNR/SYNW/SYNRW was read or written: a preprocessing stop as a
  // main-run variable's read is.
  void note_preprocessing_stop() const { ++main_run_reads_; }
  const std::string& last_input_read() const { return last_input_; }
  // How many reads let the clock run so far ($AC_TIMER, the run clock, $AA_S): a loop that polls
  // them waits for time, not only for an input it reads besides.
  uint64_t clock_reads() const { return clock_reads_; }
  // Of those, how many were of a process value that reaches its end by itself ($AA_S runs up to
  // the set speed), not of a timer that only measures a timeout.
  uint64_t process_reads() const { return process_reads_; }
  // The last poll of a process value that read what it read before ("$AA_S[1] stays at 10000"),
  // for the endless-loop alarm's text; empty when there was none.
  const std::string& settled_read() const { return settled_read_; }
  void forget_settled_read() { settled_read_.clear(); }
  // A wait on `key` ended (the loop guard took the signal as come): a digital input ($A_IN[n])
  // reads its other value from now on. Other data (bytes, words) have no one awaited value:
  // false, and they keep theirs.
  bool input_arrived(const std::string& key);
  // Whether the profile gives the input or PLC datum `key` a value (its machine_data).
  bool signal_given(const std::string& key) const { return given_signals_.count(key) > 0; }
  // The last measured value read ($AA_MW[X]); empty when the program has read none.
  const std::string& measurement_read() const { return measurement_read_; }
  // A value something outside the program may change was read (the operator at M0/M1, a
  // synchronized action): a loop that repeats after such a read waits, as on an input.
  void note_external_read(const std::string& what) const {
    ++input_reads_;
    last_input_ = what;
  }
  // A synchronized action writes `key` ("$A_OUT[5]"; a name alone: all its elements): reads of
  // it are such external reads.
  void note_sync_action_target(const std::string& key) { sync_targets_.insert(key); }

 private:
  MachineDataMap values_;                                   // machine data, I/O (from the profile)
  MachineDataTexts text_values_;                            // machine data of type STRING (profile)
  MachineDataMap written_;                                  // numbers written by the program
  std::set<std::string, std::less<>> sync_targets_;  // written by synchronized actions
  MachineDataMap timer_start_;  // running $AC_TIMER[n]: the elapsed time at which it read 0
  std::map<std::string, std::string, std::less<>> texts_;  // strings written by the program
  std::map<std::string, Value, std::less<>> frames_;        // frames written by the program
  const ControllerStateView* view_ = nullptr;
  uint64_t line_ = 0;  // lines begun (begin_line)
  mutable uint64_t view_reads_ = 0;
  mutable uint64_t input_reads_ = 0;
  mutable uint64_t main_run_reads_ = 0;
  mutable uint64_t clock_reads_ = 0;
  mutable uint64_t process_reads_ = 0;
  std::set<std::string, std::less<>> given_signals_;  // inputs and PLC data the profile gives
  mutable std::string measurement_read_;
  mutable MachineDataMap last_process_values_;  // $AA_S[n] at its last poll
  mutable std::string settled_read_;             // the last such poll that read the same again
  // Keeps the value of a polled process value (key); false when it reads what it read last time
  // (the read is then no read for the loop guard, and settled_read() names it with `why`).
  bool note_process_value(const std::string& key, const Value& v, std::string_view why) const;
  ReadResult read_process_value(std::string_view name, std::span<const Value> indices,
                                       const std::string& key) const;
  double poll_clock() const {
    ++clock_reads_;
    return view_ ? view_->poll_clock(line_) : 0.0;
  }
  mutable std::string last_input_;
};

}  // namespace drycut::parser
