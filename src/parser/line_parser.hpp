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
  // The same without the plain-word fast path (plain_word_line.hpp): tokens, then the grammar.
  // parse gives every line the result this gives it; tests compare the two.
  void parse_general(std::string_view line, ParsedLine& out);
  const std::vector<Token>& tokens() const { return tokens_; }

 private:
  void parse_tokens(ParsedLine& out);  // the general path on the line the lexer upper-cased last
  void parse_head(ParsedLine& out);
  bool parse_statement(ParsedLine& out);
  void read_sync_action(ParsedLine& out) const;
  // parse_statement's statements with a syntax of their own; true (the line is a statement).
  bool parse_extern(ParsedLine& out);
  bool parse_define(ParsedLine& out);
  bool parse_loop_condition(ParsedLine& out, Statement s);  // WHILE cond, UNTIL cond
  bool parse_for(ParsedLine& out);
  bool parse_extcall(ParsedLine& out);
  std::optional<bool> parse_call(ParsedLine& out, std::string_view w);
  void parse_section_labels(ParsedLine& out, std::string_view& start, std::string_view& end);
  void parse_redef(ParsedLine& out);
  void parse_if(ParsedLine& out);
  void parse_words(ParsedLine& out);
  // parse_words' kinds of word, from the word's name token `t` on (item: name and column set).
  void parse_assignment_word(ParsedLine& out, Item& item, const Token& t);  // NAME=.., T="..", M1=3
  void parse_r_parameter_assignment(ParsedLine& out, Item& item);            // R[i]=..
  void parse_indexed_word(ParsedLine& out, Item& item);                      // A[1,2]=.., DIAMONA[X]
  void parse_plain_word(ParsedLine& out, Item& item, const Token& t);        // G1, X10, X-6.7, NAME
  void parse_letter_digits_word(ParsedLine& out, Item& item, const Token& t, std::string_view letters,
                                int64_t digits);
  void parse_letter_number_word(ParsedLine& out, Item& item, const Token& t);
  void parse_list_assignment(ParsedLine& out, Item& item);  // PO[X]=(..), PO[]=(..), MEASA[X]=(..)
  // The values up to ')' (after '(') into the pool's argument list as item.arg_first/arg_count.
  // Whether the parenthesised group opening at token `open` has a comma at its own level.
  bool group_has_comma(size_t open) const;
  void parse_item_arguments(ParsedLine& out, Item& item, std::span<ExprIndex> buffer, bool empty_items,
                            const char* too_many);
  void parse_jump_target(ParsedLine& out);
  // A branch's own direction (CASE, a second IF ... GOTO in the block): out.jump is the line's.
  void parse_jump_target(ParsedLine& out, JumpDirection direction, JumpTarget& target);
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
