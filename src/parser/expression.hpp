#pragma once
// Expression trees of one line, stored as nodes in a pool (indices, not pointers) so a line's
// trees are built without heap allocation once the pool has grown to its working size.
#include <cstdint>
#include <string_view>
#include <vector>

namespace drycut::parser {

enum class ExprOp : uint8_t {
  Number,       // value
  String,       // text (a string literal; only valid where a string is expected)
  Name,         // text: a DEF variable, TRUE/FALSE, or a bare word such as an axis name
  RParam,       // value = index: R1
  RParamIndex,  // a = index expression: R[R2+1]
  Negate,       // a
  Not,          // a
  Add, Subtract, Multiply, Divide, IntDivide, Modulo,              // a, b
  Equal, NotEqual, Less, Greater, LessEqual, GreaterEqual,        // a, b
  And, Or, Xor,                                                     // a, b
  Call,         // function `func`, arguments args[a .. a+b)
};

enum class Function : uint8_t {
  Sin, Cos, Tan, Asin, Acos, Atan2, Sqrt, Abs, Pot, Trunc, Round, Ln, Exp, Min, Max,
  AbsoluteMode,     // AC(x): only as the whole value of an address
  IncrementalMode,  // IC(x)
};

using ExprIndex = uint32_t;
inline constexpr ExprIndex kNoExpr = UINT32_MAX;

struct ExprNode {
  ExprOp op = ExprOp::Number;
  Function func = Function::Sin;
  uint32_t column = 0;
  ExprIndex a = kNoExpr;
  ExprIndex b = kNoExpr;
  double value = 0.0;
  std::string_view text;
};

struct ExprPool {
  std::vector<ExprNode> nodes;
  std::vector<ExprIndex> args;  // call arguments, contiguous per call

  void clear() {
    nodes.clear();
    args.clear();
  }
  ExprIndex add(const ExprNode& n) {
    nodes.push_back(n);
    return static_cast<ExprIndex>(nodes.size() - 1);
  }
  const ExprNode& operator[](ExprIndex i) const { return nodes[i]; }
};

}  // namespace drycut::parser
