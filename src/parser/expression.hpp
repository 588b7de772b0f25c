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
  Name,         // text: a variable, TRUE/FALSE, a $ system variable or a bare axis name;
                // indices NAME[i, j, k] are args[a .. a+b) (b = 0: no index)
  RParam,       // value = index: R1
  RParamIndex,  // a = index expression: R[R2+1]
  Negate,       // a
  Not,          // a
  Add, Subtract, Multiply, Divide, IntDivide, Modulo,              // a, b
  Equal, NotEqual, Less, Greater, LessEqual, GreaterEqual,        // a, b
  And, Or, Xor,                                                     // a, b
  BitAnd, BitOr, BitXor, BitNot,    // B_AND B_OR B_XOR (a, b), B_NOT (a)
  Concat,                           // a << b: strings (numbers converted)
  FrameChain,                       // a : b: FRAME values chained (CTRANS(..) : CROT(..))
  Call,         // function `func`, arguments args[a .. a+b)
};

// Functions of the language; their names, argument counts and support are in
// function_table.cpp (the one table of functions).
enum class Function : uint8_t {
  Sin, Cos, Tan, Asin, Acos, Atan2, Sqrt, Abs, Pot, Trunc, Round, RoundUp, Ln, Exp, Min, Max,
  Bound, QuickOutput, IsAxis,
  ToReal, ToInt, ToBool,  // ITOR/BTOR, RTOI/BTOI, ITOB/RTOB: type conversions
  // Strings
  StrLen, Index, RIndex, MIndex, SubStr, ToUpper, ToLower, Number, IsNumber, Sprint, AxName,
  AxString, Match,
  // Answered by the program's environment (variables, tools, frames)
  IsVar, IsFile, GetT, FrameFunction, StringIs, Spindle, NameToInt,
  CircleData,  // CALCDAT(points, n, result): reads and writes arrays by reference
  Assumed,     // valid predefined function drycut does not compute: warned, FunctionInfo::assumed
  // Position modes: only as the whole value of an address
  AbsoluteMode,     // AC(x)
  IncrementalMode,  // IC(x)
  DirectMode,       // DC(x): rotary axis, shortest way
  AbsolutePositive, // ACP(x)
  AbsoluteNegative, // ACN(x)
  DiameterAbsolute, DiameterIncremental, RadiusAbsolute, RadiusIncremental,  // DAC DIC RAC RIC(x)
  PerMinute, PerRevolution,  // PM(x), PR(x): the feed type of FAD= whatever G94/G95 says
  // Array value lists: only as the whole value of an array element assignment
  ArraySet,         // NAME[i]=SET(a, b, ...): consecutive elements from i
  ArrayRep,         // NAME[i]=REP(v): element i and all after it
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
