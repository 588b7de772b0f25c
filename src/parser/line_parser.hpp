#pragma once
// Turns one line into a ParsedLine (syntax only). Owns the lexer so one LineParser, reused,
// parses a whole program without per-line allocation.
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "parser/lexer.hpp"
#include "parser/parsed_line.hpp"
#include "parser/value.hpp"

namespace drycut::parser {

class LineParser {
 public:
  // Parses `line` (decoded UTF-8, must outlive the result) into `out`. Throws LineError.
  void parse(std::string_view line, ParsedLine& out);
  const std::vector<Token>& tokens() const { return tokens_; }

 private:
  void parse_head(ParsedLine& out);
  bool parse_statement(ParsedLine& out);
  std::optional<bool> parse_call(ParsedLine& out, std::string_view w);
  void parse_section_labels(std::string_view& start, std::string_view& end);
  void parse_redef(ParsedLine& out);
  void parse_if(ParsedLine& out);
  void parse_words(ParsedLine& out);
  void parse_list_assignment(ParsedLine& out, Item& item);  // PO[X]=(..), PO[]=(..), MEASA[X]=(..)
  // The values up to ')' (after '(') into the pool's argument list as item.arg_first/arg_count.
  void parse_item_arguments(ParsedLine& out, Item& item, std::span<ExprIndex> buffer, bool empty_items,
                            const char* too_many);
  void parse_jump_target(ParsedLine& out);
  void parse_jump_target(ParsedLine& out, JumpTarget& target);
  void parse_type(DefEntry& e);
  void parse_dimensions(ParsedLine& out, DefEntry& e);
  void parse_initialiser(ParsedLine& out, DefEntry& e);
  void parse_def(ParsedLine& out);
  void skip_definition_attributes(ParsedLine& out);
  void parse_proc(ParsedLine& out);
  bool parse_case(ParsedLine& out);
  bool parse_repeat_section(ParsedLine& out, bool one_block);
  static bool jump_direction(std::string_view word, JumpDirection& d);
  ExprIndex expression(ParsedLine& out);
  void expect_end();
  const Token& peek(size_t ahead = 0) const {
    const size_t i = pos_ + ahead;
    return i < tokens_.size() ? tokens_[i] : tokens_.back();
  }

  Lexer lexer_;
  std::vector<Token> tokens_;
  std::string_view line_;  // the line as written (DEFINE keeps its text)
  size_t pos_ = 0;
};

}  // namespace drycut::parser
