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
};

enum class JumpDirection : uint8_t { Forward, Backward, ForwardThenBackward, NoAlarm };

struct JumpTarget {
  std::string_view label;        // upper case; empty when the target is a block number
  std::optional<int64_t> number; // N100 / 100
  uint32_t column = 0;
};

enum class ItemKind : uint8_t {
  G,          // code
  M,          // code, extension
  Address,    // name, expr (a literal: X12.5, Y-3)
  Assign,     // name [index], expr: X=..., R1=..., CR=..., VAR=...
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
  uint32_t column = 0;
  uint32_t arg_first = 0;  // Procedure: pool.args[arg_first .. +arg_count); kNoExpr = empty arg
  uint32_t arg_count = 0;
};

struct DefEntry {
  std::string_view name;
  ExprIndex init = kNoExpr;
  uint32_t column = 0;
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
  std::vector<DefEntry> defs;     // DEF entries; PROC parameters
  std::string_view call_name;     // CALL / PROC name
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
    defs.clear();
    call_name = {};
    items.clear();
    pool.clear();
  }
  bool is_control_structure() const {
    return statement != Statement::Words && statement != Statement::Def &&
           statement != Statement::Call && statement != Statement::Proc &&
           statement != Statement::Goto && statement != Statement::IfGoto;
  }
};

}  // namespace drycut::parser
