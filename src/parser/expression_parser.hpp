#pragma once
// Recursive-descent parser for NC expressions, with SINUMERIK operator precedence (PGA,
// "priority of operators"), highest first:
//   NOT, unary -  |  * / DIV MOD  |  + -  |  AND  |  XOR  |  OR  |  << (not supported)
//   |  == <> < > <= >=
// Comparisons bind LEAST on the control, so `R1>5 AND R2<3` reads as R1 > (5 AND R2) < 3;
// Siemens tells programmers to bracket comparisons, and so do we.
#include <span>

#include "parser/expression.hpp"
#include "parser/token.hpp"

namespace drycut::parser {

class ExpressionParser {
 public:
  ExpressionParser(std::span<const Token> tokens, size_t& position, ExprPool& pool)
      : tokens_(tokens), pos_(position), pool_(pool) {}

  // Parses one expression starting at `position` and advances it. Throws LineError.
  ExprIndex parse();

 private:
  ExprIndex comparison();
  ExprIndex logical_or();
  ExprIndex logical_xor();
  ExprIndex logical_and();
  ExprIndex additive();
  ExprIndex multiplicative();
  ExprIndex unary();
  ExprIndex primary();

  const Token& peek() const { return tokens_[pos_]; }
  bool is_name(std::string_view word) const {
    return peek().kind == TokenKind::Name && peek().text == word;
  }

  static constexpr int kMaxDepth = 200;
  std::span<const Token> tokens_;
  int depth_ = 0;
  size_t& pos_;
  ExprPool& pool_;
};

// True for a name that the expression grammar reserves (operators, functions).
bool is_expression_keyword(std::string_view upper_name);

}  // namespace drycut::parser
