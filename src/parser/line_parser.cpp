#include "parser/line_parser.hpp"

#include <charconv>
#include <cmath>
#include <limits>
#include <string>

#include "parser/command_table.hpp"
#include "parser/expression_parser.hpp"
#include "parser/line_error.hpp"
#include "parser/plain_word_line.hpp"

namespace drycut::parser {
namespace {

// Splits "G642" into letters "G" and digits "642"; false when the name is not of that shape.
bool split_letters_digits(std::string_view name, std::string_view& letters, int64_t& value) {
  size_t i = 0;
  while (i < name.size() && name[i] >= 'A' && name[i] <= 'Z') ++i;
  if (i == 0 || i == name.size()) return false;
  letters = name.substr(0, i);
  // The digits by hand (the hot path of every address word); all digits but too many for the
  // integer is still a letter+number word ("X1000...0"), not a name: the saturated value makes
  // G/M/L/P/N words fail their range checks.
  uint64_t v = 0;
  bool saturated = false;
  for (size_t k = i; k < name.size(); ++k) {
    const unsigned d = static_cast<unsigned char>(name[k]) - '0';
    if (d > 9) return false;
    if (v > (static_cast<uint64_t>(std::numeric_limits<int64_t>::max()) - d) / 10) saturated = true;
    else v = v * 10 + d;
  }
  value = saturated ? std::numeric_limits<int64_t>::max() : static_cast<int64_t>(v);
  return true;
}

bool is_block_number_name(std::string_view name, int64_t& value) {
  if (name.empty() || name[0] != 'N') return false;  // the usual answer, asked twice per line
  std::string_view letters;
  return split_letters_digits(name, letters, value) && letters == "N";
}

std::string quoted(std::string_view s) { return "'" + std::string(s) + "'"; }

}  // namespace

ExprIndex LineParser::expression(ParsedLine& out) {
  return ExpressionParser(tokens_, pos_, out.pool).parse();
}

void LineParser::expect_end() {
  if (peek().kind != TokenKind::End) {
    if (peek().kind == TokenKind::RParen) throw LineError(12080, peek().column, "unbalanced ')'");
    throw LineError(12080, peek().column, "unexpected " + quoted(peek().text));
  }
}

void LineParser::parse(std::string_view line, ParsedLine& out) {
  line_ = line;
  // Most lines of a CAM program are plain words ("G1 X12.5 Y-3"): read without tokens.
  if (parse_plain_word_line(lexer_.upper_case(line), out)) return;
  parse_tokens(out);
}

void LineParser::parse_general(std::string_view line, ParsedLine& out) {
  line_ = line;
  lexer_.upper_case(line);
  parse_tokens(out);
}

void LineParser::parse_tokens(ParsedLine& out) {
  out.clear();
  lexer_.tokenize_upper_cased(line_, tokens_);
  pos_ = 0;
  parse_head(out);
  if (parse_statement(out)) {
    if (out.is_control_structure() && (out.skip_level >= 0 || !out.label.empty()))
      throw LineError(12630, out.skip_level >= 0 ? out.skip_column : out.label_column,
                      "skip marker or label in a control-structure block");
    return;
  }
  parse_words(out);
}

void LineParser::parse_head(ParsedLine& out) {
  if (peek().kind == TokenKind::Slash) {
    out.skip_column = peek().column;
    out.skip_level = 0;
    ++pos_;
    // "/3": the level digit must follow the slash directly.
    if (peek().kind == TokenKind::Number && peek().column == out.skip_column + 1) {
      const double v = peek().number;
      if (!(v >= 0 && v <= 9) || v != static_cast<int>(v))
        throw LineError(14060, out.skip_column, "skip level " + std::string(peek().text) + " (0..9 allowed)");
      out.skip_level = static_cast<int>(v);
      ++pos_;
    }
  }
  // Block number and label, in either order: "N10 LABEL:" or "LABEL: N10".
  for (int round = 0; round < 2; ++round) {
    int64_t number = 0;
    if (!out.number && peek().kind == TokenKind::Name && is_block_number_name(peek().text, number) &&
        peek(1).kind != TokenKind::Colon) {
      out.number = number;
      out.number_column = peek().column;
      ++pos_;
    } else if (!out.number && peek().kind == TokenKind::Name && peek().text == "N" &&
               peek(1).kind == TokenKind::Number && peek(1).number >= 0 && peek(1).number == std::trunc(peek(1).number)) {
      out.number = block_number_of(peek(1).number);  // "N 20": a blank after the address, as "X 10"
      out.number_column = peek().column;
      pos_ += 2;
    } else if (!out.number && peek().kind == TokenKind::Colon && peek(1).kind == TokenKind::Number) {
      out.number = block_number_of(peek(1).number);  // ":100" main block (saturated beyond int64)
      out.number_column = peek().column;
      pos_ += 2;
    }
    // "GOTOF :30" jumps to main block 30: a jump keyword is never a label.
    JumpDirection jump;
    if (out.label.empty() && peek().kind == TokenKind::Name && peek(1).kind == TokenKind::Colon &&
        !jump_direction(peek().text, jump)) {
      out.label = peek().text;
      out.label_column = peek().column;
      pos_ += 2;
    }
  }
}

void LineParser::parse_jump_target(ParsedLine& out) { parse_jump_target(out, out.jump, out.target); }

void LineParser::parse_jump_target(ParsedLine& out, JumpDirection direction, JumpTarget& target) {
  const Token& t = peek();
  target.column = t.column;
  if (direction == JumpDirection::ToStart) return;  // GOTOS takes no target
  int64_t number = 0;
  const TokenKind after = peek(1).kind;
  const bool computed = after == TokenKind::Concat || after == TokenKind::Plus || after == TokenKind::LBracket;
  if (t.kind == TokenKind::Name && !computed && is_block_number_name(t.text, number)) {
    target.number = number;
  } else if (t.kind == TokenKind::Name && !computed) {
    target.label = t.text;  // a label, or a STRING variable holding one (decided when executed)
  } else if (t.kind == TokenKind::Number && !computed) {
    target.number = block_number_of(t.number);
  } else if (t.kind == TokenKind::Colon && after == TokenKind::Number) {
    target.number = block_number_of(peek(1).number);  // ":30", a main block number
    ++pos_;
  } else if (t.kind == TokenKind::String || t.kind == TokenKind::Name || t.kind == TokenKind::Number ||
             t.kind == TokenKind::LParen) {
    target.expr = expression(out);  // GOTOF "LBL"<<R1, GOTOF ("LBL"<<R1)
    return;
  } else {
    throw LineError(12080, t.column, "jump target (label or block number) expected");
  }
  ++pos_;
}

bool LineParser::parse_case(ParsedLine& out) {
  out.statement = Statement::Case;
  ++pos_;
  out.condition = expression(out);
  if (!(peek().kind == TokenKind::Name && peek().text == "OF")) throw LineError(12080, peek().column, "OF expected in CASE");
  ++pos_;
  while (peek().kind != TokenKind::End) {
    CaseBranch b;
    if (peek().kind == TokenKind::Name && peek().text == "DEFAULT") {
      ++pos_;
    } else {
      b.value = expression(out);
    }
    if (peek().kind != TokenKind::Name || !jump_direction(peek().text, b.jump))
      throw LineError(12080, peek().column, "GOTOF/GOTOB/GOTO/GOTOC expected in CASE");
    ++pos_;
    parse_jump_target(out, b.jump, b.target);
    const bool is_default = b.value == kNoExpr;
    out.cases.push_back(b);
    if (is_default) break;
  }
  expect_end();
  return true;
}

bool LineParser::parse_repeat_section(ParsedLine& out, bool one_block) {
  out.statement = Statement::RepeatSection;
  out.repeat_one_block = one_block;
  ++pos_;
  if (peek().kind != TokenKind::Name) throw LineError(12080, peek().column, "label expected after REPEAT");
  out.call_name = peek().text;
  out.target.column = peek().column;
  ++pos_;
  if (!one_block && peek().kind == TokenKind::Name && !(peek().text == "P" && peek(1).kind == TokenKind::Assign)) {
    out.end_label = peek().text;
    ++pos_;
  }
  if (peek().kind == TokenKind::Name && peek().text == "P" && peek(1).kind == TokenKind::Assign) {
    pos_ += 2;
    out.passes = expression(out);
  }
  expect_end();
  return true;
}

bool LineParser::jump_direction(std::string_view word, JumpDirection& d) {
  if (word == "GOTOF") d = JumpDirection::Forward;
  else if (word == "GOTOB") d = JumpDirection::Backward;
  else if (word == "GOTO") d = JumpDirection::ForwardThenBackward;
  else if (word == "GOTOC") d = JumpDirection::NoAlarm;
  else if (word == "GOTOS") d = JumpDirection::ToStart;
  else return false;
  return true;
}

// The variables a synchronized action writes: every `name =` and `name[literal, ...] =` after
// its DO (and ELSE). The program reads them as values the action may have changed. Its form is
// checked: a condition keyword (WHEN, WHENEVER, FROM, EVERY) needs a condition and then DO, and
// DO an action (Job Planning, "Motion-synchronous actions", structure of a synchronized action:
// [ID=n] [condition keyword condition] DO action; 12080 as any syntax error).
void LineParser::read_sync_action(ParsedLine& out) const {
  size_t i = 0;
  size_t condition_at = tokens_.size();  // the condition keyword's token
  while (i < tokens_.size() && !(tokens_[i].kind == TokenKind::Name && tokens_[i].text == "DO")) {
    const std::string_view w = tokens_[i].kind == TokenKind::Name ? tokens_[i].text : std::string_view();
    if (condition_at == tokens_.size() && (w == "WHEN" || w == "WHENEVER" || w == "FROM" || w == "EVERY")) condition_at = i;
    ++i;
  }
  const uint32_t end_column = tokens_.empty() ? 1 : tokens_.back().column;
  if (i == tokens_.size()) throw LineError(12080, end_column, "synchronized action without DO");
  if (condition_at + 1 == i) throw LineError(12080, tokens_[i].column, "synchronized action: no condition before DO");
  if (i + 1 >= tokens_.size() || tokens_[i + 1].kind == TokenKind::End)
    throw LineError(12080, end_column, "synchronized action: no action after DO");
  for (++i; i + 1 < tokens_.size(); ++i) {
    if (tokens_[i].kind != TokenKind::Name) continue;
    if (tokens_[i + 1].kind == TokenKind::Assign) {
      out.sync_targets.emplace_back(tokens_[i].text);
      continue;
    }
    if (tokens_[i + 1].kind != TokenKind::LBracket) continue;
    size_t j = i + 2;
    bool literal = true;
    std::string key(tokens_[i].text);
    key += '[';
    int depth = 0;  // brackets inside the index ($R[$AC_MARKER[1]])
    for (; j < tokens_.size() && tokens_[j].kind != TokenKind::End; ++j) {
      const TokenKind k = tokens_[j].kind;
      if (k == TokenKind::RBracket && depth-- == 0) break;
      if (k == TokenKind::LBracket) ++depth;
      if (k == TokenKind::Comma) key += ',';
      else if (k == TokenKind::Number) key += number_to_text(tokens_[j].number);
      else literal = false;  // a computed index (or an axis): the whole variable
    }
    if (j + 1 < tokens_.size() && tokens_[j].kind == TokenKind::RBracket && tokens_[j + 1].kind == TokenKind::Assign)
      out.sync_targets.push_back(literal ? key + ']' : std::string(tokens_[i].text));
    i = j;
  }
}

bool LineParser::parse_statement(ParsedLine& out) {
  const Token& t = peek();
  if (t.kind != TokenKind::Name) return false;
  const std::string_view w = t.text;
  out.statement_column = t.column;
  auto simple = [&](Statement s) {
    out.statement = s;
    ++pos_;
    expect_end();
    return true;
  };
  // The rest of the line is taken as it is (accepted, not executed).
  auto whole_line = [&](Statement s) {
    out.statement = s;
    out.call_name = w;
    pos_ = tokens_.size() - 1;
    return true;
  };
  if (w == "CASE") return parse_case(out);
  if (w == "REPEAT" && peek(1).kind != TokenKind::End) return parse_repeat_section(out, false);
  if (w == "REPEATB") return parse_repeat_section(out, true);
  if (w == "WHEN" || w == "WHENEVER" || w == "FROM" || w == "EVERY" || w == "DO" ||
      ((w == "ID" || w == "IDS") && peek(1).kind == TokenKind::Assign)) {
    read_sync_action(out);
    return whole_line(Statement::SyncAction);
  }
  if (w == "SETINT" || w == "ENABLE" || w == "DISABLE" || w == "CLRINT") return whole_line(Statement::Interrupt);
  if (w == "EXTERN") return parse_extern(out);
  if (w == "REDEF") {
    parse_redef(out);
    return true;
  }
  if (w == "DEFINE") return parse_define(out);
  if (w == "IF") {
    parse_if(out);
    return true;
  }
  if (w == "ELSE") return simple(Statement::Else);
  if (w == "ENDIF") return simple(Statement::EndIf);
  if (w == "ENDWHILE") return simple(Statement::EndWhile);
  if (w == "ENDFOR") return simple(Statement::EndFor);
  if (w == "REPEAT") return simple(Statement::Repeat);
  if (w == "LOOP") return simple(Statement::Loop);
  if (w == "ENDLOOP") return simple(Statement::EndLoop);
  if (w == "WHILE" || w == "UNTIL")
    return parse_loop_condition(out, w == "WHILE" ? Statement::While : Statement::Until);
  if (w == "FOR") return parse_for(out);
  if (jump_direction(w, out.jump)) {
    out.statement = Statement::Goto;
    ++pos_;
    parse_jump_target(out);
    expect_end();
    return true;
  }
  if (w == "DEF") {
    out.statement = Statement::Def;
    ++pos_;
    parse_def(out);
    return true;
  }
  if (w == "PROC") {
    out.statement = Statement::Proc;
    ++pos_;
    parse_proc(out);
    return true;
  }
  if (const std::optional<bool> call = parse_call(out, w)) return *call;
  return false;
}

// WHILE cond / UNTIL cond
bool LineParser::parse_loop_condition(ParsedLine& out, Statement s) {
  out.statement = s;
  ++pos_;
  out.condition = expression(out);
  expect_end();
  return true;
}

// FOR var = start TO end: the start value is kept as the condition.
bool LineParser::parse_for(ParsedLine& out) {
  out.statement = Statement::For;
  ++pos_;
  if (peek().kind != TokenKind::Name) throw LineError(12080, peek().column, "loop variable expected after FOR");
  out.for_variable = peek().text;
  ++pos_;
  if (peek().kind != TokenKind::Assign) throw LineError(12080, peek().column, "'=' expected after the FOR variable");
  ++pos_;
  out.condition = expression(out);
  if (!(peek().kind == TokenKind::Name && peek().text == "TO"))
    throw LineError(12080, peek().column, "TO expected in FOR");
  ++pos_;
  out.for_end = expression(out);
  expect_end();
  return true;
}

// IF cond (structured) or IF cond GOTOx target [IF cond GOTOx target ...].
void LineParser::parse_if(ParsedLine& out) {
  ++pos_;
  out.condition = expression(out);
  if (peek().kind == TokenKind::Name && jump_direction(peek().text, out.jump)) {
    out.statement = Statement::IfGoto;
    ++pos_;
    parse_jump_target(out);
    // Further conditional jumps in the same block (Job Planning, "Conditional jumps": several
    // in one block, the first whose condition holds is taken): kept as CASE-like branches.
    while (peek().kind == TokenKind::Name && peek().text == "IF") {
      ++pos_;
      CaseBranch b;
      b.value = expression(out);
      if (!(peek().kind == TokenKind::Name && jump_direction(peek().text, b.jump)))
        throw LineError(12080, peek().column, "a jump (GOTOF, GOTOB ...) expected after the condition");
      ++pos_;
      parse_jump_target(out, b.jump, b.target);
      out.cases.push_back(b);
    }
  } else {
    out.statement = Statement::If;
  }
  expect_end();
}

// "<start label> TO <end label>" of CALL [..] BLOCK, to the end of the line. Each is a label, a
// STRING variable holding one (decided when the line runs: ProgramLoader::section_label) or a
// string constant (Job Planning, "Indirect call of a program part": the labels are of type STRING).
void LineParser::parse_section_labels(ParsedLine& out, std::string_view& start, std::string_view& end) {
  out.call_block = true;
  auto label = [&](const char* expected) {
    if (peek().kind != TokenKind::Name && peek().kind != TokenKind::String) throw LineError(12080, peek().column, expected);
    const std::string_view text = peek().text;
    ++pos_;
    return text;
  };
  start = label("label expected after CALL BLOCK");
  if (!(peek().kind == TokenKind::Name && peek().text == "TO")) throw LineError(12080, peek().column, "TO expected in CALL BLOCK");
  ++pos_;
  end = label("end label expected after TO");
  expect_end();
}

// EXTCALL runs a program from an external memory (Function Manual K1, "Executing from external
// source": EXTCALL("<path/><name>")); drycut's folders are that memory, so it is a CALL. The
// form without parentheses that shop programs use is taken too.
bool LineParser::parse_extcall(ParsedLine& out) {
  out.statement = Statement::Call;
  ++pos_;
  const bool paren = peek().kind == TokenKind::LParen;
  const size_t k = paren ? 1 : 0;
  const bool plain_name = (peek(k).kind == TokenKind::String || peek(k).kind == TokenKind::Name) &&
                          (paren ? peek(k + 1).kind == TokenKind::RParen
                                 : peek(k + 1).kind != TokenKind::Concat && peek(k + 1).kind != TokenKind::LBracket);
  if (!plain_name) {
    // A computed name, EXTCALL ("PAL" << R1) or EXTCALL NAMES[2]: a STRING expression (the
    // argument's type is STRING), evaluated when the line runs, as CALL's.
    out.target.column = peek().column;
    out.target.expr = expression(out);
    expect_end();
    return true;
  }
  if (paren) ++pos_;
  if (peek().kind != TokenKind::String && peek().kind != TokenKind::Name)
    throw LineError(12080, peek().column, "program name expected after EXTCALL");
  out.call_name = peek().text;
  out.target.column = peek().column;
  ++pos_;
  if (paren) {
    if (peek().kind != TokenKind::RParen) throw LineError(12080, peek().column, "')' expected after the EXTCALL name");
    ++pos_;
  }
  expect_end();
  return true;
}

// EXTCALL, PCALL, CALL BLOCK and CALL: true when a call statement was parsed, false when the
// words go on as an ordinary subprogram call (PCALL), nullopt when `w` starts no call.
std::optional<bool> LineParser::parse_call(ParsedLine& out, std::string_view w) {
  if (w == "EXTCALL") return parse_extcall(out);
  // PCALL <path/>NAME(args): a subprogram call with an absolute path (Job Planning, "Subprogram
  // call with path specification and parameters (PCALL)"). The path names the control's
  // directory, which drycut's folders stand for: the words go on from NAME as an ordinary call.
  if (w == "PCALL") {
    ++pos_;
    while (peek().kind == TokenKind::Slash && peek(1).kind == TokenKind::Name &&
           peek(2).kind == TokenKind::Slash)
      pos_ += 2;
    if (peek().kind == TokenKind::Slash && peek(1).kind == TokenKind::Name) ++pos_;
    return false;
  }
  // CALL BLOCK <start label> TO <end label>: the program section between the labels runs once,
  // as REPEAT <start> <end> (Job Planning, "Program section repetition", indirect CALL BLOCK).
  if (w == "CALL" && peek(1).kind == TokenKind::Name && peek(1).text == "BLOCK") {
    out.statement = Statement::RepeatSection;
    out.repeat_one_block = false;
    pos_ += 2;
    out.target.column = peek().column;
    parse_section_labels(out, out.call_name, out.end_label);
    return true;
  }
  if (w == "CALL") {
    out.statement = Statement::Call;
    ++pos_;
    if (peek().kind != TokenKind::String && peek().kind != TokenKind::Name)
      throw LineError(12080, peek().column, "program name expected after CALL");
    out.target.column = peek().column;
    if (peek(1).kind == TokenKind::Concat || peek(1).kind == TokenKind::LBracket) {
      // A computed name: CALL "L" << R10, CALL NAMES[2] (Job Planning, "Indirect subprogram
      // call"): any STRING expression; evaluated when the line runs.
      out.target.expr = expression(out);
      expect_end();
      return true;
    }
    out.call_name = peek().text;
    ++pos_;
    // CALL "PROG" BLOCK start TO end: only that section of PROG runs (Job Planning, "Indirect
    // call of a program part" (CALL BLOCK)).
    if (peek().kind == TokenKind::Name && peek().text == "BLOCK") {
      ++pos_;
      parse_section_labels(out, out.section_label, out.end_label);
      return true;
    }
    // Optional passes: CALL "SUB" P3
    int64_t passes = 0;
    std::string_view letters;
    if (peek().kind == TokenKind::Name && split_letters_digits(peek().text, letters, passes) && letters == "P") {
      out.items.push_back(Item{ItemKind::Passes, peek().text, passes, -1, kNoExpr, kNoExpr, peek().column, 0, 0});
      ++pos_;
    }
    expect_end();
    return true;
  }
  return std::nullopt;
}

// PO[X]=(end, a2, ...) and PO[]=(b2, ...), MEASA[X]=(mode, trigger, ...) and MEAWA[X]=(..)
// (Job Planning, "Extended measuring function"), OSCTRL[Z]=(set, reset) (oscillation options),
// POSP[Z]=(end, part length, mode) (positioning in parts): the values are a list, as a
// procedure's arguments. All but PO may also take a single value.
void LineParser::parse_list_assignment(ParsedLine& out, Item& item) {
  const bool polynomial = item.name == "PO";
  ++pos_;  // the name
  if (polynomial && peek(1).kind == TokenKind::RBracket) {
    pos_ += 2;  // "[]": the denominator
  } else {
    ExprIndex first = kNoExpr;
    item.index_count = parse_index_list(tokens_, pos_, out.pool, first);
    item.index_first = first;
  }
  item.kind = ItemKind::Assign;
  // A single value, also in parentheses ("MEASA[X]=(R1+1)*2", or a user array of the same name,
  // "POSP[2]=(3)"), is an expression; a parenthesised group with a comma at its top is the list.
  if (!polynomial && peek().kind == TokenKind::Assign && !(peek(1).kind == TokenKind::LParen && group_has_comma(pos_ + 1))) {
    ++pos_;
    item.expr = expression(out);
    return;
  }
  if (peek().kind != TokenKind::Assign || peek(1).kind != TokenKind::LParen)
    throw LineError(12080, peek().column, std::string(item.name) + "[axis]=(values) expected");
  pos_ += 2;
  std::array<ExprIndex, 8> values{};
  parse_item_arguments(out, item, values, false, "too many values in the list");
}

bool LineParser::group_has_comma(size_t open) const {
  int depth = 0;
  for (size_t k = open; k < tokens_.size(); ++k) {
    const TokenKind kind = tokens_[k].kind;
    if (kind == TokenKind::End) return false;
    if (kind == TokenKind::LParen || kind == TokenKind::LBracket) ++depth;
    if (kind == TokenKind::RParen || kind == TokenKind::RBracket) {
      if (--depth == 0) return false;
    }
    if (kind == TokenKind::Comma && depth == 1) return true;
  }
  return false;
}

void LineParser::parse_item_arguments(ParsedLine& out, Item& item, std::span<ExprIndex> buffer, bool empty_items,
                                      const char* too_many) {
  const auto count = static_cast<uint32_t>(
      ExpressionParser(tokens_, pos_, out.pool).list(TokenKind::RParen, buffer, empty_items, too_many));
  item.arg_first = static_cast<uint32_t>(out.pool.args.size());
  item.arg_count = count;
  out.pool.args.insert(out.pool.args.end(), buffer.begin(), buffer.begin() + count);
}

void LineParser::parse_words(ParsedLine& out) {
  while (peek().kind != TokenKind::End) {
    const Token& t = peek();
    if (t.kind != TokenKind::Name) {
      if (t.kind == TokenKind::RParen) throw LineError(12080, t.column, "unbalanced ')'");
      throw LineError(12080, t.column, "unexpected " + quoted(t.text));
    }
    Item item;
    item.name = t.text;
    item.column = t.column;
    const Token& next = peek(1);
    if (next.kind == TokenKind::Assign) {
      parse_assignment_word(out, item, t);
    } else if (t.text == "R" && next.kind == TokenKind::LBracket) {
      parse_r_parameter_assignment(out, item);
    } else if ((t.text == "PO" || t.text == "MEASA" || t.text == "MEAWA" || t.text == "OSCTRL" || t.text == "POSP") &&
               next.kind == TokenKind::LBracket) {
      parse_list_assignment(out, item);
    } else if (next.kind == TokenKind::LBracket) {
      parse_indexed_word(out, item);
    } else if (next.kind == TokenKind::LParen) {
      pos_ += 2;
      item.kind = ItemKind::Procedure;
      // Arguments may be empty: CYCLE800(,"TABLE",1)
      std::array<ExprIndex, 64> args{};
      parse_item_arguments(out, item, args, true, "too many arguments");
    } else {
      ++pos_;
      parse_plain_word(out, item, t);
    }
    out.items.push_back(item);
  }
}

// NAME=value; T="name" (a tool by name), M1=3 (spindle 1, M3).
void LineParser::parse_assignment_word(ParsedLine& out, Item& item, const Token& t) {
  pos_ += 2;
  int64_t ext = 0;
  std::string_view letters;
  if (t.text == "T" && peek().kind == TokenKind::String) {
    item.kind = ItemKind::ToolName;
    item.name = peek().text;  // case preserved
    ++pos_;
  } else if (split_letters_digits(t.text, letters, ext) && letters == "M") {
    item.kind = ItemKind::M;  // M1=3: spindle 1, M3
    item.extension = static_cast<int>(ext);
    item.expr = expression(out);
  } else {
    item.kind = ItemKind::Assign;
    item.expr = expression(out);
  }
}

// R[index]=value
void LineParser::parse_r_parameter_assignment(ParsedLine& out, Item& item) {
  pos_ += 2;
  item.kind = ItemKind::Assign;
  item.index = expression(out);
  if (peek().kind != TokenKind::RBracket) throw LineError(12080, peek().column, "missing ']'");
  ++pos_;
  if (peek().kind != TokenKind::Assign) throw LineError(12080, peek().column, "'=' expected");
  ++pos_;
  item.expr = expression(out);
}

// A[1,2]=..., $MA_COMPRESS_POS_TOL[X1]=..., G[8]=2, M[2]=3, S[1]=1000; DIAMONA[X] without a value.
void LineParser::parse_indexed_word(ParsedLine& out, Item& item) {
  ++pos_;
  ExprIndex first = kNoExpr;
  item.index_count = parse_index_list(tokens_, pos_, out.pool, first);
  item.index_first = first;
  item.kind = ItemKind::Assign;
  if (peek().kind != TokenKind::Assign && is_axis_indexed_command(item.name)) {
    item.kind = ItemKind::Name;  // DIAMONA[X], SCC[X]: a command with an axis, no value
    return;
  }
  if (peek().kind != TokenKind::Assign) throw LineError(12080, peek().column, "'=' expected after an array element");
  ++pos_;
  item.expr = expression(out);
}

// A word followed by no '=', '[' or '(' (its name token already taken): "G642", "X10",
// "X-6.789", "X 12", or a name (a command, a subprogram call).
void LineParser::parse_plain_word(ParsedLine& out, Item& item, const Token& t) {
  std::string_view letters;
  int64_t digits = 0;
  const bool letter_digits = split_letters_digits(t.text, letters, digits) && letters.size() == 1;
  if (letter_digits) {
    parse_letter_digits_word(out, item, t, letters, digits);
  } else if (t.text.size() == 1 && t.text[0] != '_' && t.text[0] != '$' &&
             (peek().kind == TokenKind::Number ||
              ((peek().kind == TokenKind::Minus || peek().kind == TokenKind::Plus) &&
               peek(1).kind == TokenKind::Number))) {
    parse_letter_number_word(out, item, t);
  } else {
    item.kind = ItemKind::Name;
  }
}

// One letter and its digits in one token: "G642", "M3", "L100", "P2", "X0012".
void LineParser::parse_letter_digits_word(ParsedLine& out, Item& item, const Token& t, std::string_view letters,
                                          int64_t digits) {
  item.name = letters;
  switch (letters[0]) {
    case 'G': item.kind = ItemKind::G; item.code = digits; break;
    case 'M': item.kind = ItemKind::M; item.code = digits; break;
    case 'L': item.kind = ItemKind::LCall; item.code = digits; item.name = t.text; break;
    case 'P': item.kind = ItemKind::Passes; item.code = digits; break;
    case 'N': throw LineError(12080, t.column, "block number must stand at the start of the block");
    case 'R': throw LineError(12080, t.column, "R parameter without '=' assignment");
    default: {
      item.kind = ItemKind::Address;
      // The digits as written: "X0012" is 12, value parsed from the text, not the int.
      double v = static_cast<double>(digits);  // exact below 2^53
      if (digits >= (int64_t{1} << 53) &&
          std::from_chars(t.text.data() + 1, t.text.data() + t.text.size(), v).ec != std::errc())
        throw LineError(12080, t.column + 1, "malformed number " + quoted(t.text.substr(1)));
      item.expr = out.pool.add(ExprNode{ExprOp::Number, Function::Sin, t.column + 1, kNoExpr, kNoExpr, v, t.text.substr(1)});
    }
  }
}

// "X-6.789", "X.5", "X 12": an address letter with a signed literal (a token of its own).
void LineParser::parse_letter_number_word(ParsedLine& out, Item& item, const Token& t) {
  double sign = 1.0;
  if (peek().kind != TokenKind::Number) {
    sign = peek().kind == TokenKind::Minus ? -1.0 : 1.0;
    ++pos_;
  }
  const Token& num = peek();
  ++pos_;
  const double v = sign * num.number;
  const char letter = t.text[0];
  if (letter == 'G' || letter == 'M' || letter == 'L' || letter == 'P' || letter == 'N' || letter == 'R') {
    // Range before the conversion: a double beyond int64 is undefined behaviour there.
    if (letter == 'N' || letter == 'R' || v < 0 || v >= 9.2e18 || v != std::trunc(v))
      throw LineError(12080, t.column, "malformed " + std::string(t.text) + " word");
    item.code = static_cast<int64_t>(v);
    item.kind = letter == 'G' ? ItemKind::G : letter == 'M' ? ItemKind::M : letter == 'L' ? ItemKind::LCall : ItemKind::Passes;
  } else {
    item.kind = ItemKind::Address;
    item.expr = out.pool.add(ExprNode{ExprOp::Number, Function::Sin, num.column, kNoExpr, kNoExpr, v, num.text});
  }
}

}  // namespace drycut::parser
