// The declarations of the language, parsed: DEF (type, attributes, dimensions, initial values),
// PROC parameters, EXTERN, DEFINE ... AS and REDEF (Job Planning, "Definition of user data",
// "Subprograms with parameter transfer", "Macro technique", "REDEF").
#include <string>

#include "parser/expression_parser.hpp"
#include "parser/line_error.hpp"
#include "parser/line_parser.hpp"

namespace drycut::parser {

namespace {

// Attributes of GUD definitions (Job Planning, "Definition of user data"): preprocessing stop
// (SYNR, SYNW, SYNRW), initialisation time (INIPO, INIRE, INICF), unit, limits and access rights
// (PHU, LLI, ULI, APR..., with a value), before or after the type:
// DEF NCK SYNR INIPO REAL PHU 1 LLI 0 ULI 1000 SPEEDLIM. Only the limits LLI/ULI change what
// drycut does: a write outside them is warned (ProgramLoader::within_limits).
bool is_definition_attribute(std::string_view w) {
  return w == "PHU" || w == "LLI" || w == "ULI" || w == "PRLOC" || w == "APR" || w == "APW" ||
         w == "APRP" || w == "APWP" || w == "APRB" || w == "APWB" || w == "SYNR" || w == "SYNW" ||
         w == "SYNRW" || w == "INIPO" || w == "INIRE" || w == "INICF";
}

}  // namespace

void LineParser::parse_type(DefEntry& e) {
  const Token& type = peek();
  DataType t;
  if (type.kind != TokenKind::Name || !parse_data_type(type.text, t))
    throw LineError(12080, type.column, "a type is needed: INT REAL BOOL CHAR STRING AXIS FRAME");
  e.type = type.text;
  ++pos_;
  if (e.type == "STRING") {  // STRING[32]
    if (peek().kind != TokenKind::LBracket || peek(1).kind != TokenKind::Number ||
        peek(2).kind != TokenKind::RBracket)
      throw LineError(12080, peek().column, "STRING needs a length: STRING[n]");
    const double n = peek(1).number;
    if (n < 1 || n > 400 || n != static_cast<int>(n)) throw LineError(12160, peek(1).column, "STRING length must be 1..400");
    e.string_length = static_cast<uint32_t>(n);
    pos_ += 3;
  }
}

// "[3]", "[2,3]", "[,5]" (open dimension of a PROC array parameter): the dimension expressions.
void LineParser::parse_dimensions(ParsedLine& out, DefEntry& e) {
  ++pos_;  // '['
  if (peek().kind == TokenKind::RBracket) {  // ARR[]: one open dimension (a PROC parameter)
    ++pos_;
    e.rank = 1;
    return;
  }
  e.rank = static_cast<uint8_t>(ExpressionParser(tokens_, pos_, out.pool)
                                    .list(TokenKind::RBracket, e.dims, true, "more than 3 array dimensions"));
}

// "= v", "= (a, b, c)", "= SET(a, b, c)", "= REP(v)"
void LineParser::parse_initialiser(ParsedLine& out, DefEntry& e) {
  ++pos_;  // '='
  const bool set = peek().kind == TokenKind::Name && peek().text == "SET" && peek(1).kind == TokenKind::LParen;
  const bool rep = peek().kind == TokenKind::Name && peek().text == "REP" && peek(1).kind == TokenKind::LParen;
  if (set || rep) ++pos_;
  if (!(set || rep || (peek().kind == TokenKind::LParen && e.rank > 0))) {
    e.init_kind = InitKind::Single;
    e.init = expression(out);
    return;
  }
  ++pos_;  // '('
  std::vector<ExprIndex> buffer(tokens_.size());  // never more values than tokens
  const size_t n = ExpressionParser(tokens_, pos_, out.pool).list(TokenKind::RParen, buffer, false, "too many values");
  const std::span<const ExprIndex> values(buffer.data(), n);
  if (rep) {
    if (values.size() != 1) throw LineError(12080, e.column, "REP takes one value");
    e.init_kind = InitKind::Rep;
    e.init = values.front();
    return;
  }
  e.init_kind = InitKind::List;
  e.init_first = static_cast<uint32_t>(out.pool.args.size());
  e.init_count = static_cast<uint32_t>(values.size());
  out.pool.args.insert(out.pool.args.end(), values.begin(), values.end());
}

void LineParser::skip_definition_attributes(ParsedLine& out) {
  while (peek().kind == TokenKind::Name && is_definition_attribute(peek().text)) {
    const std::string_view attribute = peek().text;
    ++pos_;
    if (attribute == "SYNR" || attribute == "SYNRW") out.def_stop_on_read = true;
    if (attribute == "SYNW" || attribute == "SYNRW") out.def_stop_on_write = true;
    if (peek().kind == TokenKind::End || peek().kind == TokenKind::Name) continue;
    const ExprIndex value = expression(out);
    if (attribute == "LLI") out.def_lower_limit = value;  // the limits are checked on writes
    if (attribute == "ULI") out.def_upper_limit = value;
  }
}

void LineParser::parse_def(ParsedLine& out) {
  if (peek().kind == TokenKind::Name && (peek().text == "NCK" || peek().text == "CHAN")) {
    out.def_scope = peek().text;
    ++pos_;
  }
  DefEntry proto;
  skip_definition_attributes(out);
  parse_type(proto);
  out.def_type = proto.type;
  skip_definition_attributes(out);
  for (;;) {
    const Token& name = peek();
    if (name.kind != TokenKind::Name || is_expression_keyword(name.text))
      throw LineError(12080, name.column, "variable name expected");
    DefEntry e = proto;
    e.name = name.text;
    e.column = name.column;
    ++pos_;
    if (peek().kind == TokenKind::LBracket) parse_dimensions(out, e);
    if (peek().kind == TokenKind::Assign) parse_initialiser(out, e);
    out.defs.push_back(e);
    if (peek().kind != TokenKind::Comma) break;
    ++pos_;
  }
  expect_end();
}

void LineParser::parse_proc(ParsedLine& out) {
  if (peek().kind != TokenKind::Name) throw LineError(12080, peek().column, "program name expected after PROC");
  out.call_name = peek().text;
  ++pos_;
  if (peek().kind == TokenKind::LParen) {
    ++pos_;
    while (peek().kind != TokenKind::RParen) {
      // "REAL A", "INT B", "VAR REAL C", "VAR REAL S[3]", "STRING[32] NAME"
      DefEntry e;
      if (peek().kind == TokenKind::Name && peek().text == "VAR") {
        e.by_reference = true;
        ++pos_;
      }
      parse_type(e);
      if (peek().kind != TokenKind::Name) throw LineError(12080, peek().column, "parameter name expected");
      e.name = peek().text;
      e.column = peek().column;
      ++pos_;
      if (peek().kind == TokenKind::LBracket) parse_dimensions(out, e);
      out.defs.push_back(e);
      if (peek().kind == TokenKind::Comma) {
        ++pos_;
        continue;
      }
      if (peek().kind != TokenKind::RParen) throw LineError(12080, peek().column, "missing ')' in PROC");
    }
    ++pos_;
  }
  // SAVE restores the modal state at the return; DISPLOF, SBLOF, ACTBLOCNO ... change nothing
  // for a dry run.
  while (peek().kind == TokenKind::Name) {
    if (peek().text == "SAVE") out.proc_save = true;
    ++pos_;
  }
  expect_end();
}

bool LineParser::parse_extern(ParsedLine& out) {
  ++pos_;
  if (peek().kind != TokenKind::Name) throw LineError(12080, peek().column, "program name expected after EXTERN");
  out.statement = Statement::Extern;
  out.call_name = peek().text;
  pos_ = tokens_.size() - 1;  // the parameter types declare nothing drycut needs
  return true;
}

// DEFINE name AS text: the text is kept as written, up to a comment.
bool LineParser::parse_define(ParsedLine& out) {
  ++pos_;
  if (peek().kind != TokenKind::Name || !(peek(1).kind == TokenKind::Name && peek(1).text == "AS"))
    throw LineError(12080, peek().column, "DEFINE name AS text expected");
  out.statement = Statement::Define;
  out.call_name = peek().text;
  const uint32_t text_column = peek(2).column;
  out.macro_text = line_.substr(std::min<size_t>(text_column - 1, line_.size()));
  // The comment starts at the first ';' outside a string: MSG("Tuer; zu") keeps its text.
  bool in_string = false;
  for (size_t c = 0; c < out.macro_text.size(); ++c) {
    if (out.macro_text[c] == '"') in_string = !in_string;
    if (out.macro_text[c] == ';' && !in_string) {
      out.macro_text = out.macro_text.substr(0, c);
      break;
    }
  }
  pos_ = tokens_.size() - 1;
  return true;
}

// REDEF name attributes (Job Planning, "Redefinition of system variables, user variables and
// NC language commands (REDEF)"), in definition files: new access rights (APR/APW/APRP/APWP/
// APRB/APWB, APX for a command), preprocessing stop, initialisation, unit or limits of a
// name. Nothing drycut computes changes: a declaration, checked for its form only.
void LineParser::parse_redef(ParsedLine& out) {
  ++pos_;
  if (peek().kind != TokenKind::Name) throw LineError(12080, peek().column, "name expected after REDEF");
  out.statement = Statement::Extern;
  out.call_name = peek().text;
  ++pos_;
  if (peek().kind == TokenKind::LBracket) {  // REDEF $MA_..[AX1]
    while (peek().kind != TokenKind::RBracket && peek().kind != TokenKind::End) ++pos_;
    if (peek().kind == TokenKind::RBracket) ++pos_;
  }
  while (peek().kind == TokenKind::Name && (is_definition_attribute(peek().text) || peek().text == "APX")) {
    ++pos_;
    if (peek().kind == TokenKind::Minus || peek().kind == TokenKind::Plus) ++pos_;
    if (peek().kind == TokenKind::Number) ++pos_;
  }
  expect_end();
}

}  // namespace drycut::parser
