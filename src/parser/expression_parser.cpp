#include "parser/expression_parser.hpp"

#include <array>
#include <charconv>
#include <string>

#include "parser/function_table.hpp"
#include "parser/line_error.hpp"

namespace drycut::parser {
namespace {

constexpr std::array<std::string_view, 10> kOperatorWords{"AND", "OR", "XOR", "NOT", "DIV", "MOD",
                                                         "B_AND", "B_OR", "B_XOR", "B_NOT"};

// "R12" -> 12; -1 when the name is not an R parameter.
long r_parameter_index(std::string_view name) {
  if (name.size() < 2 || name[0] != 'R') return -1;
  long v = 0;
  const auto r = std::from_chars(name.data() + 1, name.data() + name.size(), v);
  return (r.ec == std::errc() && r.ptr == name.data() + name.size()) ? v : -1;
}

}  // namespace

bool is_expression_keyword(std::string_view name) {
  // SET and REP are only value lists of array assignments: elsewhere they stay free names.
  if (const FunctionInfo* f = find_function(name))
    return f->func != Function::ArraySet && f->func != Function::ArrayRep;
  for (auto w : kOperatorWords)
    if (w == name) return true;
  return false;
}

ExprIndex ExpressionParser::parse() { return frame_chain(); }

// `:` chains FRAME values (PGA Job Planning "Frames": CTRANS(X,10) : CROT(Z,30)); lowest priority.
void ExpressionParser::count_chain(int& length, uint32_t column) const {
  if (++length > kMaxChain) throw LineError(12080, column, "too many operators in one chain");
}

ExprIndex ExpressionParser::frame_chain() {
  ExprIndex left = comparison();
  int length = 0;
  while (peek().kind == TokenKind::Colon) {
    const uint32_t column = peek().column;
    count_chain(length, column);
    ++pos_;
    left = pool_.add(ExprNode{ExprOp::FrameChain, Function::Sin, column, left, comparison(), 0.0, {}});
  }
  return left;
}

ExprIndex ExpressionParser::comparison() {
  ExprIndex left = concatenation();
  for (int length = 0;;) {
    ExprOp op;
    switch (peek().kind) {
      case TokenKind::Equal: op = ExprOp::Equal; break;
      case TokenKind::NotEqual: op = ExprOp::NotEqual; break;
      case TokenKind::Less: op = ExprOp::Less; break;
      case TokenKind::Greater: op = ExprOp::Greater; break;
      case TokenKind::LessEqual: op = ExprOp::LessEqual; break;
      case TokenKind::GreaterEqual: op = ExprOp::GreaterEqual; break;
      default: return left;
    }
    const uint32_t column = peek().column;
    count_chain(length, column);
    ++pos_;
    const ExprIndex right = concatenation();
    left = pool_.add(ExprNode{op, Function::Sin, column, left, right, 0.0, {}});
  }
}

ExprIndex ExpressionParser::concatenation() {
  ExprIndex left = logical_or();
  int length = 0;
  while (peek().kind == TokenKind::Concat) {
    const uint32_t column = peek().column;
    count_chain(length, column);
    ++pos_;
    left = pool_.add(ExprNode{ExprOp::Concat, Function::Sin, column, left, logical_or(), 0.0, {}});
  }
  return left;
}

ExprIndex ExpressionParser::binary_level(std::string_view op_word, ExprOp op,
                                         ExprIndex (ExpressionParser::*next)()) {
  ExprIndex left = (this->*next)();
  while (is_name(op_word)) {
    const uint32_t column = peek().column;
    ++pos_;
    left = pool_.add(ExprNode{op, Function::Sin, column, left, (this->*next)(), 0.0, {}});
  }
  return left;
}

ExprIndex ExpressionParser::logical_or() { return binary_level("OR", ExprOp::Or, &ExpressionParser::logical_xor); }
ExprIndex ExpressionParser::logical_xor() { return binary_level("XOR", ExprOp::Xor, &ExpressionParser::logical_and); }
ExprIndex ExpressionParser::logical_and() { return binary_level("AND", ExprOp::And, &ExpressionParser::bit_or); }
ExprIndex ExpressionParser::bit_or() { return binary_level("B_OR", ExprOp::BitOr, &ExpressionParser::bit_xor); }
ExprIndex ExpressionParser::bit_xor() { return binary_level("B_XOR", ExprOp::BitXor, &ExpressionParser::bit_and); }
ExprIndex ExpressionParser::bit_and() { return binary_level("B_AND", ExprOp::BitAnd, &ExpressionParser::additive); }

ExprIndex ExpressionParser::additive() {
  ExprIndex left = multiplicative();
  for (;;) {
    ExprOp op;
    if (peek().kind == TokenKind::Plus)
      op = ExprOp::Add;
    else if (peek().kind == TokenKind::Minus)
      op = ExprOp::Subtract;
    else
      return left;
    const uint32_t column = peek().column;
    ++pos_;
    const ExprIndex right = multiplicative();
    left = pool_.add(ExprNode{op, Function::Sin, column, left, right, 0.0, {}});
  }
}

ExprIndex ExpressionParser::multiplicative() {
  ExprIndex left = unary();
  for (;;) {
    ExprOp op;
    if (peek().kind == TokenKind::Star)
      op = ExprOp::Multiply;
    else if (peek().kind == TokenKind::Slash)
      op = ExprOp::Divide;
    else if (is_name("DIV"))
      op = ExprOp::IntDivide;
    else if (is_name("MOD"))
      op = ExprOp::Modulo;
    else
      return left;
    const uint32_t column = peek().column;
    ++pos_;
    const ExprIndex right = unary();
    left = pool_.add(ExprNode{op, Function::Sin, column, left, right, 0.0, {}});
  }
}

ExprIndex ExpressionParser::unary() {
  const uint32_t column = peek().column;
  // Every nesting level passes through here: bound it so a hostile line cannot blow the stack.
  struct DepthGuard {
    int& depth;
    explicit DepthGuard(int& d, uint32_t col) : depth(d) {
      if (++depth > kMaxDepth) throw LineError(12080, col, "expression nested too deeply");
    }
    ~DepthGuard() { --depth; }
  } guard(depth_, column);
  if (peek().kind == TokenKind::Minus) {
    ++pos_;
    return pool_.add(ExprNode{ExprOp::Negate, Function::Sin, column, unary(), kNoExpr, 0.0, {}});
  }
  if (peek().kind == TokenKind::Plus) {
    ++pos_;
    return unary();
  }
  if (is_name("NOT") || is_name("B_NOT")) {
    const ExprOp op = is_name("NOT") ? ExprOp::Not : ExprOp::BitNot;
    ++pos_;
    return pool_.add(ExprNode{op, Function::Sin, column, unary(), kNoExpr, 0.0, {}});
  }
  return primary();
}

ExprIndex ExpressionParser::primary() {
  const Token& t = peek();
  switch (t.kind) {
    case TokenKind::Number:
      ++pos_;
      return pool_.add(ExprNode{ExprOp::Number, Function::Sin, t.column, kNoExpr, kNoExpr, t.number, t.text});
    case TokenKind::String:
      ++pos_;
      return pool_.add(ExprNode{ExprOp::String, Function::Sin, t.column, kNoExpr, kNoExpr, 0.0, t.text});
    case TokenKind::LParen: {
      ++pos_;
      const ExprIndex inner = parse();
      if (peek().kind != TokenKind::RParen)
        throw LineError(12080, peek().column, "missing ')'");
      ++pos_;
      return inner;
    }
    case TokenKind::Name: {
      ++pos_;
      if (t.text == "R" && peek().kind == TokenKind::LBracket) {
        ++pos_;
        const ExprIndex index = parse();
        if (peek().kind != TokenKind::RBracket) throw LineError(12080, peek().column, "missing ']'");
        ++pos_;
        return pool_.add(ExprNode{ExprOp::RParamIndex, Function::Sin, t.column, index, kNoExpr, 0.0, t.text});
      }
      if (const long r = r_parameter_index(t.text); r >= 0)
        return pool_.add(ExprNode{ExprOp::RParam, Function::Sin, t.column, kNoExpr, kNoExpr, static_cast<double>(r), t.text});
      if (peek().kind == TokenKind::LParen) return function_call(t);
      if (is_expression_keyword(t.text))
        throw LineError(12080, t.column, "operator " + std::string(t.text) + " without operand");
      ExprIndex first = kNoExpr;
      const uint32_t count = peek().kind == TokenKind::LBracket ? indices(first) : 0;
      return pool_.add(ExprNode{ExprOp::Name, Function::Sin, t.column, first, count, 0.0, t.text});
    }
    case TokenKind::End:
      throw LineError(12080, t.column, "expression expected");
    default:
      throw LineError(12080, t.column, "unexpected '" + std::string(t.text) + "' in expression");
  }
}

ExprIndex ExpressionParser::function_call(const Token& t) {
  const FunctionInfo* f = find_function(t.text);
  if (!f) throw LineError(12550, t.column, "unknown function " + std::string(t.text));
  ++pos_;
  std::array<ExprIndex, 32> args{};
  const size_t count = list(TokenKind::RParen, args, false, "too many arguments");
  if (count < f->min_args || count > f->max_args)
    throw LineError(12080, t.column, "wrong number of arguments for " + std::string(f->name));
  const auto first = static_cast<ExprIndex>(pool_.args.size());
  pool_.args.insert(pool_.args.end(), args.begin(), args.begin() + static_cast<long>(count));
  return pool_.add(ExprNode{ExprOp::Call, f->func, t.column, first, static_cast<ExprIndex>(count), 0.0, t.text});
}

uint32_t ExpressionParser::indices(ExprIndex& first) {
  ++pos_;  // '['
  std::array<ExprIndex, 3> idx{};
  if (peek().kind == TokenKind::RBracket) throw LineError(12080, peek().column, "index expected");
  const auto count = static_cast<uint32_t>(list(TokenKind::RBracket, idx, false, "more than 3 array indices"));
  first = static_cast<ExprIndex>(pool_.args.size());
  pool_.args.insert(pool_.args.end(), idx.begin(), idx.begin() + count);
  return count;
}

size_t ExpressionParser::list(TokenKind close, std::span<ExprIndex> out, bool empty_items, const char* too_many) {
  size_t count = 0;
  if (peek().kind != close) {
    for (;;) {
      if (count == out.size()) throw LineError(12080, peek().column, too_many);
      const bool empty = peek().kind == TokenKind::Comma || peek().kind == close;
      if (empty && !empty_items) throw LineError(12080, peek().column, "expression expected");
      out[count++] = empty ? kNoExpr : parse();
      if (peek().kind != TokenKind::Comma) break;
      ++pos_;
    }
  }
  if (peek().kind != close)
    throw LineError(12080, peek().column, close == TokenKind::RBracket ? "missing ']'" : "missing ')'");
  ++pos_;
  return count;
}

uint32_t parse_index_list(std::span<const Token> tokens, size_t& position, ExprPool& pool, ExprIndex& first) {
  ExpressionParser parser(tokens, position, pool);
  return parser.index_list(first);
}

}  // namespace drycut::parser
