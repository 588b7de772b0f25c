#include "parser/expression_parser.hpp"

#include <array>
#include <charconv>
#include <string>

#include "parser/line_error.hpp"

namespace drycut::parser {
namespace {

struct FunctionName {
  std::string_view name;
  Function func;
  uint8_t min_args;
  uint8_t max_args;
};

constexpr std::array kFunctions{
    FunctionName{"SIN", Function::Sin, 1, 1},     FunctionName{"COS", Function::Cos, 1, 1},
    FunctionName{"TAN", Function::Tan, 1, 1},     FunctionName{"ASIN", Function::Asin, 1, 1},
    FunctionName{"ACOS", Function::Acos, 1, 1},   FunctionName{"ATAN2", Function::Atan2, 2, 2},
    FunctionName{"SQRT", Function::Sqrt, 1, 1},   FunctionName{"ABS", Function::Abs, 1, 1},
    FunctionName{"POT", Function::Pot, 1, 2},     FunctionName{"TRUNC", Function::Trunc, 1, 1},
    FunctionName{"ROUND", Function::Round, 1, 1}, FunctionName{"LN", Function::Ln, 1, 1},
    FunctionName{"EXP", Function::Exp, 1, 1},     FunctionName{"MINVAL", Function::Min, 2, 2},
    FunctionName{"MAXVAL", Function::Max, 2, 2},  FunctionName{"AC", Function::AbsoluteMode, 1, 1},
    FunctionName{"IC", Function::IncrementalMode, 1, 1},
};

constexpr std::array<std::string_view, 8> kOperatorWords{"AND", "OR", "XOR", "NOT", "DIV", "MOD", "B_AND", "B_OR"};

const FunctionName* find_function(std::string_view name) {
  for (const auto& f : kFunctions)
    if (f.name == name) return &f;
  return nullptr;
}

// "R12" -> 12; -1 when the name is not an R parameter.
long r_parameter_index(std::string_view name) {
  if (name.size() < 2 || name[0] != 'R') return -1;
  long v = 0;
  const auto r = std::from_chars(name.data() + 1, name.data() + name.size(), v);
  return (r.ec == std::errc() && r.ptr == name.data() + name.size()) ? v : -1;
}

}  // namespace

bool is_expression_keyword(std::string_view name) {
  if (find_function(name)) return true;
  for (auto w : kOperatorWords)
    if (w == name) return true;
  return false;
}

ExprIndex ExpressionParser::parse() { return comparison(); }

ExprIndex ExpressionParser::comparison() {
  ExprIndex left = logical_or();
  for (;;) {
    ExprOp op;
    switch (peek().kind) {
      case TokenKind::Equal: op = ExprOp::Equal; break;
      case TokenKind::NotEqual: op = ExprOp::NotEqual; break;
      case TokenKind::Less: op = ExprOp::Less; break;
      case TokenKind::Greater: op = ExprOp::Greater; break;
      case TokenKind::LessEqual: op = ExprOp::LessEqual; break;
      case TokenKind::GreaterEqual: op = ExprOp::GreaterEqual; break;
      case TokenKind::Concat:
        throw LineError(12080, peek().column, "string concatenation << is not supported");
      default: return left;
    }
    const uint32_t column = peek().column;
    ++pos_;
    const ExprIndex right = logical_or();
    left = pool_.add(ExprNode{op, Function::Sin, column, left, right, 0.0, {}});
  }
}

ExprIndex ExpressionParser::logical_or() {
  ExprIndex left = logical_xor();
  while (is_name("OR")) {
    const uint32_t column = peek().column;
    ++pos_;
    left = pool_.add(ExprNode{ExprOp::Or, Function::Sin, column, left, logical_xor(), 0.0, {}});
  }
  return left;
}

ExprIndex ExpressionParser::logical_xor() {
  ExprIndex left = logical_and();
  while (is_name("XOR")) {
    const uint32_t column = peek().column;
    ++pos_;
    left = pool_.add(ExprNode{ExprOp::Xor, Function::Sin, column, left, logical_and(), 0.0, {}});
  }
  return left;
}

ExprIndex ExpressionParser::logical_and() {
  ExprIndex left = additive();
  while (is_name("AND")) {
    const uint32_t column = peek().column;
    ++pos_;
    left = pool_.add(ExprNode{ExprOp::And, Function::Sin, column, left, additive(), 0.0, {}});
  }
  return left;
}

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
  if (is_name("NOT")) {
    ++pos_;
    return pool_.add(ExprNode{ExprOp::Not, Function::Sin, column, unary(), kNoExpr, 0.0, {}});
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
      if (peek().kind == TokenKind::LParen) {
        const FunctionName* f = find_function(t.text);
        if (!f) throw LineError(12550, t.column, "unknown function " + std::string(t.text));
        ++pos_;
        std::array<ExprIndex, 8> args{};
        size_t count = 0;
        if (peek().kind != TokenKind::RParen) {
          for (;;) {
            if (count == args.size()) throw LineError(12080, peek().column, "too many arguments");
            args[count++] = parse();
            if (peek().kind == TokenKind::Comma) {
              ++pos_;
              continue;
            }
            break;
          }
        }
        if (peek().kind != TokenKind::RParen) throw LineError(12080, peek().column, "missing ')'");
        ++pos_;
        if (count < f->min_args || count > f->max_args)
          throw LineError(12080, t.column, "wrong number of arguments for " + std::string(f->name));
        const auto first = static_cast<ExprIndex>(pool_.args.size());
        pool_.args.insert(pool_.args.end(), args.begin(), args.begin() + static_cast<long>(count));
        return pool_.add(ExprNode{ExprOp::Call, f->func, t.column, first, static_cast<ExprIndex>(count), 0.0, t.text});
      }
      if (is_expression_keyword(t.text))
        throw LineError(12080, t.column, "operator " + std::string(t.text) + " without operand");
      return pool_.add(ExprNode{ExprOp::Name, Function::Sin, t.column, kNoExpr, kNoExpr, 0.0, t.text});
    }
    case TokenKind::End:
      throw LineError(12080, t.column, "expression expected");
    default:
      throw LineError(12080, t.column, "unexpected '" + std::string(t.text) + "' in expression");
  }
}

}  // namespace drycut::parser
