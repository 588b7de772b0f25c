#pragma once
// The interpreter's state as `$` system variables, for the loader: programmed state ($P_GG,
// $P_EP, $P_F, $P_TOOLNO, $P_TOOL ...), actual state ($AA_IM, $AA_IW: in a dry run the actual
// position is the programmed one) and tool data ($TC_DP3 length, $TC_DP6 radius). The loader
// reads them while it prepares the next block, after the interpreter executed the previous
// one: the values are those of the control's block preparation (STOPRE changes nothing here).
#include <optional>
#include <span>
#include <string_view>

#include "interp/interpreter.hpp"
#include "machine/machine_profile.hpp"
#include "parser/system_variables.hpp"

namespace drycut::interp {

class InterpreterStateView : public parser::ControllerStateView {
 public:
  // Not const: a read of the run clock waits for the main run (Interpreter::poll_clock).
  InterpreterStateView(Interpreter& interpreter, const machine::MachineProfile& profile)
      : interpreter_(interpreter), profile_(profile) {}
  std::optional<parser::Value> read_system_variable(std::string_view upper_name,
                                                    std::span<const parser::Value> indices) const override;
  double elapsed_s() const override { return interpreter_.nominal_time_s(); }
  double poll_clock(uint64_t line) const override { return interpreter_.poll_clock(line); }
  double cutting_time_s() const override { return interpreter_.cutting_time_s(); }
  bool changes_while_polled(std::string_view upper_name, std::span<const parser::Value> indices) const override;
  std::optional<double> frame_component(std::string_view frame_text, std::string_view axis,
                                        std::string_view component) const override;
  std::optional<std::string> frame_with_component(std::string_view frame_text, std::string_view axis,
                                                  std::string_view component, double value) const override;

 private:
  std::optional<double> g_group_index(int group) const;
  std::optional<parser::Value> tool_variable(std::string_view name, std::span<const parser::Value> indices) const;
  std::optional<parser::Value> tool_presence(std::string_view name, std::span<const parser::Value> indices) const;
  // $P_PFRAME, $P_UIFR[n], $P_IFRAME, $P_ACTFRAME ... whole or [axis, component] (frame_variable_reads.cpp).
  std::optional<parser::Value> frame_variable(std::string_view name, std::span<const parser::Value> indices) const;
  std::optional<int> spindle_index(std::span<const parser::Value> indices) const;
  std::optional<parser::Value> spindle_speed(bool actual, std::span<const parser::Value> indices) const;
  // `actual`: where the machine is ($AA_IM, $AA_IW), else the programmed point ($P_EP).
  std::optional<double> axis_position(std::span<const parser::Value> indices, bool workpiece, bool actual) const;
  std::optional<double> tool_datum(int parameter, std::span<const parser::Value> indices) const;
  static int settable_frame_number(const std::string& work_offset);  // G54 -> 1 ...
  static parser::Value frame_value(const Frame& frame, double unit);  // CFRAME(...) text

  Interpreter& interpreter_;
  const machine::MachineProfile& profile_;
};

}  // namespace drycut::interp
