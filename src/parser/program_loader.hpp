#pragma once
// The program loader: walks a main program and its subprograms and produces the executed
// block stream, one evaluated Block at a time. Calls, passes, jumps and control structures are
// followed lazily (a stack of program frames, each streaming its file), so the expanded program
// never exists in memory. Call/jump/control/DEF/assignment-only blocks are consumed here.
//
// It is split by concept over several files:
//   program_loader.cpp        reading lines, the call stack (calls, passes, returns), alarms
//   loader_scope.cpp          names: variables, R parameters, $ system variables, axis names
//   loader_definitions.cpp    DEF, PROC parameters, definition files (GUD/MAC), DEFINE macros
//   loader_control_flow.cpp   IF/WHILE/FOR/REPEAT/LOOP, GOTO*, CASE, REPEAT sections,
//                             endless loops (loop_guard.hpp)
//   block_builder.cpp         the words of an ordinary block -> Block
#include <array>
#include <bitset>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "machine/alarm.hpp"
#include "parser/block.hpp"
#include "parser/line_parser.hpp"
#include "parser/line_reader.hpp"
#include "parser/loop_guard.hpp"
#include "parser/parsed_line.hpp"
#include "parser/program_files.hpp"
#include "parser/system_variables.hpp"
#include "parser/variable_store.hpp"

namespace drycut::parser {

struct LoaderOptions {
  std::vector<std::filesystem::path> search_path;  // searched after the main program's folder
  uint64_t max_steps = 100'000'000;                 // lines executed before alarm 990004
  std::array<bool, 10> skip_levels_active{};        // /0 ... /9 switched on: such blocks skipped
  // A call of a program that is not found is warning 14011 (once per name) instead of an alarm.
  bool missing_programs_warn = false;
  // Folders of definition files (GUD/MAC .DEF); *.DEF beside the main program are read too.
  std::vector<std::filesystem::path> definition_dirs;
  // The first this many of them are drycut's own (CYCLE_MACROS.DEF, MEASURING_CYCLES_GUD.DEF):
  // the names they define, the machine's own definition files may define again.
  size_t standard_definition_dirs = 0;
  // Machine and setting data, inputs and PLC data by `$` name ("$MA_COMPRESS_POS_TOL[X1]").
  MachineDataMap machine_data;
  MachineDataTexts machine_data_texts;  // machine data of type STRING (axis names)
  // Axis names of the machine beyond the standard X Y Z A B C U V W (and their numbered forms).
  std::vector<std::string> axis_names;
};

// An argument of a subprogram call: its value, and for VAR parameters what it refers to.
struct CallArgument {
  Value value;
  bool given = false;
  Variable* variable = nullptr;  // a variable (whole array when element is SIZE_MAX)
  size_t element = 0;
  double* r_parameter = nullptr;
};

// MCALL name(args): called after every block with axis motion until MCALL alone (PGA
// Fundamentals "Modal subprogram call (MCALL)"); not inside the called subprogram itself.
struct ModalCall {
  std::string name;
  std::vector<CallArgument> args;  // values
  uint32_t column = 0;
};

class ProgramLoader {
 public:
  // Program levels: main = 0, deepest subprogram = kMaxProgramLevel (16 levels in all).
  static constexpr int kMaxProgramLevel = 15;

  ProgramLoader(LoaderOptions options, Diagnostics& diagnostics);
  ~ProgramLoader();
  ProgramLoader(const ProgramLoader&) = delete;
  ProgramLoader& operator=(const ProgramLoader&) = delete;

  // Throws UsageError when the file cannot be read.
  void open_main(const std::filesystem::path& path);
  // The interpreter's programmed state answers $P_/$AA_/$TC_ reads (in `run`).
  void set_state_view(const ControllerStateView* view) {
    system_variables_.set_view(view);
    state_view_ = view;
  }
  // Fills `out` with the next executed block; false at program end. Throws AlarmError.
  bool next(Block& out);

  const std::vector<std::string>& programs_used() const { return programs_used_; }
  uint64_t blocks_executed() const { return blocks_executed_; }
  uint64_t steps() const { return steps_; }  // lines executed, including consumed ones
  // Distinct G/M words and commands executed: "G1", "M30", "ASPLINE", ... sorted.
  std::vector<std::string> commands_used() const;

 private:
  struct Frame;
  struct ControlFrame;
  struct RepeatSection;
  class Scope;
  class BlockBuilder;
  friend class BlockBuilder;

  enum class PendingAction : uint8_t { None, Call, Return, EndProgram };
  // A parameterised RET(target, after, levels, to_start): where the return goes on.
  struct ReturnRequest {
    std::optional<Value> target;  // label (string) or block number in the program returned to
    bool after_target = false;    // continue after the target block, not at it
    int levels = 1;               // program levels to return over
    bool to_start = false;        // continue at the start of the program returned to
  };
  ReturnRequest return_request_;
  int return_levels_left_ = 0;

  // program_loader.cpp
  bool read_line(Frame& f);  // next line into text_/position_; false at end of file
  void return_one_level();   // RET/M17, one program level (RET(...) may ask for more)
  void count_line();          // a line starts: the step limit, the system variables' line count
  bool take_pending_line();   // EXECSTRING's text becomes the line; false: nothing to run
  bool execute_line(Block& out);
  void call_program(const std::string& written_name, uint64_t passes, uint32_t column);
  // A called program that is a section of an archive file already open; false when none is.
  bool call_archived_program(const ProgramName& name, uint64_t passes);
  void push_called_frame(std::unique_ptr<Frame> frame, const std::string& program, uint64_t passes);
  // After a block with axis motion: the MCALL subprogram is due (not from inside it).
  void schedule_modal_call(const Block& block);
  void end_of_file();
  void finish_frame();
  double eval(ExprIndex e) const;
  Value eval_value(ExprIndex e) const;
  void warn_not_modelled(std::string_view name, uint32_t column);
  // A program of this name is in the search path (a user's NUT.SPF beside the keyword NUT=).
  bool has_program(std::string_view name) const;
  void warn(int number, const std::string& text, uint32_t column);
  [[noreturn]] void raise(int number, const std::string& detail, uint32_t column) const;
  // block_builder.cpp
  bool execute_words(Block& out);
  // loader_scope.cpp
  Variable* find_variable(std::string_view name);
  bool is_axis_name(std::string_view name) const;
  // $ variables the loader answers itself: $P_SUBPAR[n], $P_PROG, $P_PROGPATH.
  std::optional<Value> program_variable(std::string_view name, std::span<const Value> indices) const;
  void assign_variable(Variable& v, uint32_t index_first, uint32_t index_count, ExprIndex value, uint32_t column);
  // x, after warning when it lies outside v's LLI/ULI.
  const Value& within_limits(const Variable& v, const Value& x, uint32_t column);
  void assign_r_parameter(double index, double value, uint32_t column);
  void assign_system_variable(const Item& item, Block& out);
  CallArgument call_argument(ExprIndex e);
  // loader_definitions.cpp
  // `from_definition_file`: a name drycut's own definition files defined is defined anew (the
  // machine's own GUD files, read after drycut's, win), not alarm 12170.
  void execute_def(bool from_definition_file = false);
  // Blank, comment or tape-leader lines before the file's own header: the program starts there.
  static void start_at_own_header(Frame& f);
  void execute_proc();
  Variable make_variable(const DefEntry& d);
  void initialise(Variable& v, const DefEntry& d);
  void read_definition_files(const std::filesystem::path& main_folder);
  void read_definition_file(const std::filesystem::path& file);
  void define_macro(std::string_view name, std::string_view text);
  bool may_hold_macro() const;  // cheap pre-check: a name in text_ starts like a macro name
  void expand_macros();
  // loader_control_flow.cpp
  void execute_control();
  void start_for_loop(ControlFrame& c, uint32_t column);  // FOR
  void next_for_pass(Frame& f, uint32_t column);          // ENDFOR
  void repeat_loop_body(Frame& f, const std::string& awaited = {});  // UNTIL (false), ENDLOOP
  void execute_if_goto();
  void execute_case();
  void execute_repeat_section();
  void run_program_section(const std::string& start_label, const std::string& end_label, uint32_t column);
  std::string section_label(std::string_view written);
  // The section START:END of `program`, or (empty) of the program that called the running one:
  // a contour cycle's contour.
  void call_contour_section(const std::string& program, const std::string& start_label, const std::string& end_label,
                            uint32_t column);
  bool end_of_repeat_section(Frame& f);
  // At every backward jump: alarm 990004 when the loader is back in a state it had here.
  // After a backward jump: raises 990004 when the loader is back in a state it had (an endless
  // loop); true when the repeating loop reads inputs (it waits for them: the caller leaves it).
  // `awaited`: the input the condition that takes this jump back read (a wait on it); empty: none.
  bool check_endless_loop(const std::string& awaited = {});
  // The input this line's condition read (empty: none).
  std::string condition_input() const;
  // For a jump back to `target_line`: this line's condition, or for a GOTOB of its own the IF
  // block that directly wraps it and starts after the target (W1: / IF $A_IN[4]==0 / GOTOB W1).
  std::string jump_awaited_input(uint32_t target_line) const;
  // An IF-GOTO decided by an input remembers it (input_jump_); a SETAL in a branch an input the
  // profile does not give decided names that input (the alarm is then only warned, 990021).
  void note_input_jump();
  std::string alarm_decided_by_unknown_input(int alarm) const;
  void loop_state(std::string& out) const;
  void jump(JumpDirection direction, const JumpTarget& target);
  void jump_to_start();
  void jump_to_value(JumpDirection direction, const Value& target, uint32_t column);  // GOTO "L"<<R1, RET("L")
  void jump_to(JumpDirection direction, const std::string& label, std::optional<int64_t> number, uint32_t column);
  std::optional<LinePosition> find_label_position(const std::string& label);
  // The first (`last`: the last) line labelled `label` from `from` on, before byte offset
  // `before`; a marker N<digits> is that block number.
  std::optional<LinePosition> find_label_between(const std::string& label, LinePosition from, uint64_t before,
                                                 bool last = false);
  Statement skip_forward(bool stop_at_else);
  void parse_during_search(Frame& f);
  void push_control(const ControlFrame& c);

  LoaderOptions options_;
  bool reading_standard_definitions_ = false;  // read_definition_files: in drycut's own folder
  Diagnostics& diagnostics_;
  std::unique_ptr<ProgramFiles> files_;
  struct ArchivedProgram {
    FileName file = nullptr;
    ArchiveSection section;
  };
  // Programs looked for in open archive files, by "NAME.EXT" (nullopt: in none of them).
  std::unordered_map<std::string, std::optional<ArchivedProgram>> archived_programs_;
  std::vector<std::unique_ptr<Frame>> frames_;
  std::unique_ptr<Scope> scope_;
  std::vector<double> r_parameters_;
  size_t r_used_ = 0;  // R parameters from r_used_ on were never written (all 0)
  VariableTable globals_;  // GUD: definition files
  bool program_global_data_ = false;  // MD11120 LUD_EXTENDED_SCOPE: main program variables are PUD
  SystemVariables system_variables_;
  bool sync_actions_seen_ = false;  // a synchronized action or interrupt was programmed ($Rn polls wait)
  // What synchronized actions write (after DO): R parameters (any spelling), user variables by
  // name. The program reads them as values the actions may have changed (note_external_read).
  std::set<double> sync_written_r_;
  bool sync_actions_writes_all_r_ = false;  // $R[computed index]
  std::set<std::string, std::less<>> sync_written_names_;
  void note_sync_action_targets();
  std::map<std::string, std::string, std::less<>> macros_;  // DEFINE name AS text
  std::array<bool, 256> macro_initials_{};  // first letters of the macro names (both cases)
  std::string macro_initial_list_;           // the same letters, each once
  LoopGuard loop_guard_;
  std::string loop_state_;  // reused buffer
  uint64_t next_loop_check_ = 0;  // steps_ before which a backward jump is not checked (big states)

  LineParser parser_;
  ParsedLine parsed_;
  RawLine raw_;
  std::string text_;  // current line, decoded (macros expanded)
  std::string search_label_;  // the label of a line the parser refused during a search (parse_during_search)
  LinePosition position_;

  PendingAction pending_ = PendingAction::None;
  std::optional<std::string> pending_line_;  // EXECSTRING's text: runs before the next line is read
  int exec_string_chain_ = 0;                  // EXECSTRING lines run since the last line read
  ModalSave pending_save_ = ModalSave::None;  // told to the interpreter with the next block
  std::string pending_call_;
  // DRYCUT_CONTOUR_CALL("[PROG:]START:END"): the section to run instead (no PROG: of the caller).
  std::string pending_section_program_, pending_section_start_, pending_section_end_;
  uint64_t pending_passes_ = 1;
  uint32_t pending_column_ = 0;
  std::vector<CallArgument> pending_args_;
  bool pending_is_modal_call_ = false;   // the pending call is the modal call (MCALL)
  std::optional<ModalCall> modal_call_;
  std::optional<Alarm> definition_alarm_;  // from a definition file: raised by the first next()

  std::vector<std::string> programs_used_;
  std::set<std::string, std::less<>> missing_programs_;
  uint64_t blocks_executed_ = 0;
  uint64_t main_run_reads_seen_ = 0;  // system_variables_.main_run_reads() at the last block
  uint64_t steps_ = 0;
  uint64_t input_reads_at_endfor_ = 0;  // input reads at the last ENDFOR (next_for_pass)
  uint64_t input_reads_at_loop_check_ = 0;  // input reads at the last check_endless_loop
  std::pair<std::string, uint64_t> input_jump_;  // the input that decided the last jump, steps_ then
  const ControllerStateView* state_view_ = nullptr;  // frames of FRAME variables (components)
  uint64_t work_blocks_ = 0;   // blocks handed on that move axes or program M functions or S
  uint64_t dwell_blocks_ = 0;  // G4 blocks handed on (a wait loop dwells between its polls)
  void count_handed_block(const Block& out);
  uint64_t input_reads_at_line_ = 0;   // system_variables_.input_reads() when this line began
  bool main_has_content_ = false;
  std::bitset<1000> g_used_, m_used_;
  std::set<std::string, std::less<>> commands_used_;
  std::set<std::string> warned_;
};

}  // namespace drycut::parser
