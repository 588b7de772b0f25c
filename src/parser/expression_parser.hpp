#pragma once
// Recursive-descent parser for NC expressions, with SINUMERIK operator precedence (PGA,
// "priority of operators"), highest first:
//   NOT, B_NOT, unary -  |  * / DIV MOD  |  + -  |  B_AND  |  B_XOR  |  B_OR  |  AND  |  XOR
//   |  OR  |  <<  |  == <> < > <= >=
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
  // Parses "[i, j, k]" (position at '['); returns the count, `first` indexes pool.args.
  uint32_t index_list(ExprIndex& first) { return indices(first); }
  // The items "a, b, c" up to and including the token `close` (the opener is already read):
  // at most out.size() (else 12080 `too_many`); `empty_items` lets an item be left out
  // (kNoExpr), as in CYCLE81(10,,2). An empty list before `close` has no items.
  size_t list(TokenKind close, std::span<ExprIndex> out, bool empty_items, const char* too_many);

 private:
  ExprIndex frame_chain();
  ExprIndex comparison();
  ExprIndex concatenation();
  ExprIndex logical_or();
  ExprIndex logical_xor();
  ExprIndex logical_and();
  ExprIndex bit_or();
  ExprIndex bit_xor();
  ExprIndex bit_and();
  ExprIndex additive();
  ExprIndex multiplicative();
  ExprIndex unary();
  ExprIndex primary();
  ExprIndex function_call(const Token& name);
  // "[i, j, k]" after a name: the index expressions into pool.args; returns the count.
  uint32_t indices(ExprIndex& first);
  // Left-associative binary operator level: `op_word` between operands of `next`.
  ExprIndex binary_level(std::string_view op_word, ExprOp op, ExprIndex (ExpressionParser::*next)());

  const Token& peek() const { return tokens_[pos_]; }
  bool is_name(std::string_view word) const {
    return peek().kind == TokenKind::Name && peek().text == word;
  }

  static constexpr int kMaxDepth = 200;
  // Operators in one chain of comparisons, `<<` or `:`. A chain is a left-deep tree that the
  // evaluator walks recursively with large frames (values, not numbers), so its length is its
  // stack depth: 18,000 `==` overflowed the stack. No program chains more than a few; the
  // numeric levels (+ - * / AND ...) take chains as long as a block with small frames.
  static constexpr int kMaxChain = 500;
  void count_chain(int& length, uint32_t column) const;
  std::span<const Token> tokens_;
  int depth_ = 0;
  size_t& pos_;
  ExprPool& pool_;
};

// True for a name that the expression grammar reserves (operators, functions).
bool is_expression_keyword(std::string_view upper_name);
// Parses "[e1, e2, ...]" at `position` (which must be at '[') into pool.args; returns the
// count (1..3) and sets `first`. Used for array elements on both sides of '='.
uint32_t parse_index_list(std::span<const Token> tokens, size_t& position, ExprPool& pool, ExprIndex& first);

}  // namespace drycut::parser
