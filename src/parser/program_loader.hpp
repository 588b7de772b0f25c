#pragma once
// The program loader: walks a main program and its subprograms and produces the executed
// block stream, one evaluated Block at a time. Calls, passes, jumps and control structures are
// followed lazily (a stack of program frames, each streaming its file), so the expanded program
// never exists in memory. Call/jump/control/DEF/assignment-only blocks are consumed here.
#include <array>
#include <bitset>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "machine/alarm.hpp"
#include "parser/block.hpp"
#include "parser/line_parser.hpp"
#include "parser/line_reader.hpp"
#include "parser/parsed_line.hpp"
#include "parser/program_files.hpp"

namespace drycut::parser {

struct LoaderOptions {
  std::vector<std::filesystem::path> search_path;  // searched after the main program's folder
  uint64_t max_steps = 100'000'000;                 // lines executed before alarm 990004
  std::array<bool, 10> skip_levels_active{};        // /0 ... /9 switched on: such blocks skipped
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
  class Scope;

  enum class PendingAction : uint8_t { None, Call, Return, EndProgram };

  bool read_line(Frame& f);  // next line into text_/position_; false at end of file
  bool execute_line(Block& out);
  bool execute_words(Block& out);
  void execute_control();
  void execute_def();
  void execute_proc();
  void jump(JumpDirection direction, const std::string& label, std::optional<int64_t> number, uint32_t column);
  Statement skip_forward(bool stop_at_else);
  void call_program(const std::string& written_name, uint64_t passes, uint32_t column);
  void end_of_file();
  void finish_frame();
  void push_control(const ControlFrame& c);
  void assign(const Item& item);
  double eval(ExprIndex e) const;
  void warn_not_modelled(std::string_view name, uint32_t column);
  [[noreturn]] void raise(int number, const std::string& detail, uint32_t column) const;

  LoaderOptions options_;
  Diagnostics& diagnostics_;
  std::unique_ptr<ProgramFiles> files_;
  std::vector<std::unique_ptr<Frame>> frames_;
  std::unique_ptr<Scope> scope_;
  std::vector<double> r_parameters_;

  LineParser parser_;
  ParsedLine parsed_;
  RawLine raw_;
  std::string text_;  // current line, decoded
  LinePosition position_;

  PendingAction pending_ = PendingAction::None;
  std::string pending_call_;
  uint64_t pending_passes_ = 1;
  uint32_t pending_column_ = 0;
  std::vector<double> pending_args_;

  std::vector<std::string> programs_used_;
  uint64_t blocks_executed_ = 0;
  uint64_t steps_ = 0;
  bool main_has_content_ = false;
  std::bitset<1000> g_used_, m_used_;
  std::set<std::string, std::less<>> commands_used_;
  std::set<std::string> warned_;
};

}  // namespace drycut::parser
