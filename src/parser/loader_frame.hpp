#pragma once
// Internal to the loader's files: one level of the call stack (a program being executed) and
// the open control structures and REPEAT sections inside it.
#include <string>
#include <unordered_map>
#include "machine/source_location.hpp"
#include <vector>

#include "parser/expression_evaluator.hpp"
#include "parser/program_loader.hpp"

namespace drycut::parser {

struct ProgramLoader::ControlFrame {
  Statement kind = Statement::If;
  LinePosition head;  // the opening line
  LinePosition body;  // the line after it
  double end = 0.0;   // FOR: last value
  std::string variable;  // FOR: loop variable
  std::string awaited_input;  // IF/WHILE: the input or PLC datum its condition read last (empty: none)
  bool in_else = false;       // IF: its ELSE part runs (a second ELSE is a nesting error)
};

// REPEAT start [end] P=n / REPEATB: lines from `start` up to (not including) `stop` are run
// `remaining` more times, then reading goes on at `resume`.
struct ProgramLoader::RepeatSection {
  LinePosition start;
  uint64_t stop_offset = 0;
  LinePosition resume;
  uint64_t remaining = 0;
};

struct ProgramLoader::Frame {
  FileName file = nullptr;  // as shown in alarms
  std::string program;                      // upper-case program name
  LineReader reader;
  // Where the program's first line is: 0, or in an archive file holding several programs the
  // line after its %_N_NAME_SPF header (the reader ends at the next header).
  LinePosition start;
  uint64_t passes_left = 1;
  std::vector<CallArgument> args;  // call arguments, bound by PROC
  std::vector<ControlFrame> control;
  std::vector<RepeatSection> repeats;
  std::unordered_map<std::string, LinePosition> labels;  // labels passed so far
  VariableTable locals;            // LUD
  bool executed_block = false;     // DEF is only allowed before the first executable block
  bool save = false;               // PROC ... SAVE: the caller's modal state comes back at the return
  bool modal_call = false;         // runs the MCALL subprogram: no modal call from inside it
};

// Values of names for the expression evaluator.
class ProgramLoader::Scope : public VariableSource {
 public:
  explicit Scope(ProgramLoader& loader) : loader_(loader) {}
  Value variable(std::string_view name, std::span<const Value> indices, uint32_t column) const override;
  double r_parameter(double index, uint32_t column) const override;
  Value environment_function(const ExprNode& call, std::span<const Value> args) const override;
  Value reference_function(const ExprNode& call, const ExprPool& pool) const override;

 private:
  Value circle_data(const ExprNode& call, const ExprPool& pool) const;
  // The environment functions that need the loader (loader_scope.cpp).
  Value isvar_value(const ExprNode& call, std::span<const Value> args) const;
  static bool index_within(const Variable& v, std::string_view index_text);
  Value isfile_value(const ExprNode& call, std::span<const Value> args) const;
  Value stringis_value(const ExprNode& call, std::span<const Value> args) const;
  Value nametoint_value(const ExprNode& call, std::span<const Value> args) const;
  Value gett_value(const ExprNode& call, std::span<const Value> args) const;
  ProgramLoader& loader_;
};

// Blanks, tabs and the other non-printable characters, which the control treats as blanks
// (Fundamentals, "Character set": tape codes DC2/DC4, NUL leaders, a stray CR or form feed).
inline bool is_blank_char(char c) {
  const auto b = static_cast<unsigned char>(c);
  return b == ' ' || b < 0x20 || b == 0x7F;
}

inline std::string_view trimmed(std::string_view s) {
  while (!s.empty() && is_blank_char(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_blank_char(s.back())) s.remove_suffix(1);
  return s;
}

// A program header line "%_N_NAME_MPF" / "%_N_NAME_SPF": in an archive file, where the next program
// begins (reading, label searches and forward jumps end there).
inline bool is_program_header(std::string_view bytes) {
  while (!bytes.empty() && (bytes.front() == ' ' || bytes.front() == '\t')) bytes.remove_prefix(1);
  return bytes.size() > 4 && bytes[0] == '%' && bytes[1] == '_' && (bytes[2] == 'N' || bytes[2] == 'n') && bytes[3] == '_';
}

inline bool is_blank_or_comment(std::string_view line) {
  const std::string_view t = trimmed(line);
  return t.empty() || t.front() == ';' || t.front() == '%';
}

inline bool is_opener(Statement s) {
  return s == Statement::If || s == Statement::While || s == Statement::For || s == Statement::Repeat ||
         s == Statement::Loop;
}
inline bool is_closer(Statement s) {
  return s == Statement::EndIf || s == Statement::EndWhile || s == Statement::EndFor || s == Statement::Until ||
         s == Statement::EndLoop;
}
inline Statement closer_of(Statement opener) {
  switch (opener) {
    case Statement::If: return Statement::EndIf;
    case Statement::While: return Statement::EndWhile;
    case Statement::For: return Statement::EndFor;
    case Statement::Repeat: return Statement::Until;
    default: return Statement::EndLoop;
  }
}
inline const char* statement_keyword(Statement s) {
  switch (s) {
    case Statement::If: return "IF";
    case Statement::Else: return "ELSE";
    case Statement::EndIf: return "ENDIF";
    case Statement::While: return "WHILE";
    case Statement::EndWhile: return "ENDWHILE";
    case Statement::For: return "FOR";
    case Statement::EndFor: return "ENDFOR";
    case Statement::Repeat: return "REPEAT";
    case Statement::Until: return "UNTIL";
    case Statement::Loop: return "LOOP";
    case Statement::EndLoop: return "ENDLOOP";
    default: return "?";
  }
}

}  // namespace drycut::parser
