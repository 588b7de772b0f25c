#pragma once
// The syntax tree of one NC line: what the parser saw, nothing evaluated. Names are views into
// the lexer's upper-case buffer; all vectors are reused from line to line.
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "parser/expression.hpp"

namespace drycut::parser {

enum class Statement : uint8_t {
  Words,     // an ordinary block: G/M words, addresses, assignments, commands, calls
  If,        // IF cond            (structured)
  IfGoto,    // IF cond GOTOx target
  Else,
  EndIf,
  While,
  EndWhile,
  For,       // FOR var = start TO end
  EndFor,
  Repeat,
  Until,
  Loop,
  EndLoop,
  Goto,      // GOTOF / GOTOB / GOTO / GOTOC target
  Def,       // DEF type name [= value], ...
  Call,      // CALL "name" / CALL name
  Proc,      // PROC name(params)
  Case,      // CASE expr OF const GOTOx target ... DEFAULT GOTOx target
  RepeatSection,  // REPEAT start [end] [P=n] / REPEATB label [P=n]
  Extern,    // EXTERN name(types): a declaration, nothing to execute
  Define,    // DEFINE name AS text (a macro)
  SyncAction,  // [ID=n] WHEN/WHENEVER/FROM/EVERY ... DO ...: accepted, not modelled
  Interrupt,   // SETINT/ENABLE/DISABLE/CLRINT: accepted, not modelled
};

// ToStart: GOTOS, back to the first executable block of the program (no target).
enum class JumpDirection : uint8_t { Forward, Backward, ForwardThenBackward, NoAlarm, ToStart };

// A block number from a numeric value: beyond the int64 range (or NaN) it saturates, as a
// written N word with too many digits does (no such block exists: 14080, or nothing for GOTOC).
inline int64_t block_number_of(double v) {
  constexpr double kLimit = 9.2e18;  // below INT64_MAX, exactly representable
  if (!(v > -kLimit)) return v < 0 ? -static_cast<int64_t>(kLimit) : static_cast<int64_t>(kLimit);
  return v < kLimit ? static_cast<int64_t>(v) : static_cast<int64_t>(kLimit);
}

struct JumpTarget {
  std::string_view label;        // upper case; empty when the target is a block number
  std::optional<int64_t> number; // N100 / 100
  ExprIndex expr = kNoExpr;      // a computed target (STRING expression or number)
  uint32_t column = 0;
};

struct CaseBranch {
  ExprIndex value = kNoExpr;     // kNoExpr: DEFAULT
  JumpDirection jump = JumpDirection::Forward;
  JumpTarget target;
};

enum class ItemKind : uint8_t {
  G,          // code
  M,          // code, extension
  Address,    // name, expr (a literal: X12.5, Y-3)
  Assign,     // name [indices], expr: X=..., R1=..., CR=..., VAR=..., A[1,2]=..., G[8]=2
  Procedure,  // name(args): CYCLE832(0.01,1), MSG("..."), SUB(1,2)
  Name,       // a bare word: ASPLINE, SOFT, RET, EKVI_POSTUPNE_45
  ToolName,   // T="name": text
  LCall,      // L123: code
  Passes,     // P3: code
};

struct Item {
  ItemKind kind = ItemKind::Name;
  std::string_view name;  // upper case (ToolName: the name as written)
  int64_t code = 0;
  int extension = -1;     // M1=3 -> 1
  ExprIndex expr = kNoExpr;
  ExprIndex index = kNoExpr;  // R[index]=...
  uint32_t index_first = 0;   // NAME[i, j, k]=...: pool.args[index_first .. +index_count)
  uint32_t index_count = 0;
  uint32_t column = 0;
  uint32_t arg_first = 0;  // Procedure: pool.args[arg_first .. +arg_count); kNoExpr = empty arg
  uint32_t arg_count = 0;
};

enum class InitKind : uint8_t { None, Single, List, Rep };  // =v, =(a, b) or =SET(a, b), =REP(v)

struct DefEntry {
  std::string_view name;
  ExprIndex init = kNoExpr;    // Single, Rep
  uint32_t column = 0;
  InitKind init_kind = InitKind::None;
  uint32_t init_first = 0;     // List: pool.args[init_first .. +init_count)
  uint32_t init_count = 0;
  uint8_t rank = 0;            // array dimensions (0: scalar)
  ExprIndex dims[3] = {kNoExpr, kNoExpr, kNoExpr};
  std::string_view type;       // INT REAL ... (PROC parameters each have their own)
  uint32_t string_length = 0;  // STRING[n]
  bool by_reference = false;   // PROC parameter with VAR
};

struct ParsedLine {
  int skip_level = -1;  // -1: no skip marker; "/" = 0, "/3" = 3
  uint32_t skip_column = 0;
  std::optional<int64_t> number;
  uint32_t number_column = 0;
  std::string_view label;
  uint32_t label_column = 0;

  Statement statement = Statement::Words;
  uint32_t statement_column = 0;
  ExprIndex condition = kNoExpr;  // IF, WHILE, UNTIL; FOR: start value
  ExprIndex for_end = kNoExpr;
  std::string_view for_variable;
  JumpDirection jump = JumpDirection::Forward;
  JumpTarget target;
  std::string_view def_type;      // INT REAL BOOL CHAR STRING AXIS FRAME
  std::string_view def_scope;     // DEF NCK / CHAN (definition files); empty: local
  ExprIndex def_lower_limit = kNoExpr;  // DEF ... LLI <value> (attribute of the definition)
  bool def_stop_on_read = false;   // DEF ... SYNR / SYNRW: a read stops preprocessing
  bool def_stop_on_write = false;  // DEF ... SYNW / SYNRW: a write stops preprocessing
  ExprIndex def_upper_limit = kNoExpr;  // DEF ... ULI <value>
  std::vector<DefEntry> defs;     // DEF entries; PROC parameters
  std::string_view call_name;     // CALL / PROC / EXTERN / DEFINE / REPEAT start name
  std::string_view end_label;     // REPEAT start end, CALL "PROG" BLOCK start TO end: the end label
  std::string_view section_label;  // CALL "PROG" BLOCK start TO end: the start label
  bool repeat_one_block = false;  // REPEATB
  bool call_block = false;        // CALL [..] BLOCK: its labels may be STRING variables
  bool proc_save = false;         // PROC ... SAVE
  ExprIndex passes = kNoExpr;     // REPEAT ... P=n
  std::string_view macro_text;    // DEFINE name AS <text> (as written)
  // A synchronized action's assignment targets after DO/ELSE: "$R20", "$A_OUT[5]", "GUD_NOCKE";
  // a name alone when its index is not a literal (all its elements).
  std::vector<std::string> sync_targets;
  std::vector<CaseBranch> cases;  // CASE branches, DEFAULT last
  std::vector<Item> items;
  ExprPool pool;

  void clear() {
    skip_level = -1;
    number.reset();
    label = {};
    statement = Statement::Words;
    condition = for_end = kNoExpr;
    for_variable = {};
    target = {};
    def_type = {};
    def_scope = {};
    def_lower_limit = def_upper_limit = kNoExpr;
    def_stop_on_read = def_stop_on_write = false;
    defs.clear();
    call_name = {};
    end_label = {};
    section_label = {};
    repeat_one_block = false;
    call_block = false;
    proc_save = false;
    passes = kNoExpr;
    macro_text = {};
    sync_targets.clear();
    cases.clear();
    items.clear();
    pool.clear();
  }
  bool is_control_structure() const {
    switch (statement) {
      case Statement::Words: case Statement::Def: case Statement::Call: case Statement::Proc:
      case Statement::Goto: case Statement::IfGoto: case Statement::Case: case Statement::RepeatSection:
      case Statement::Extern: case Statement::Define: case Statement::SyncAction: case Statement::Interrupt:
        return false;
      default:
        return true;
    }
  }
};

}  // namespace drycut::parser
