#include "parser/expression_evaluator.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "parser/line_error.hpp"

namespace drycut::parser {
namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;
constexpr double kRadToDeg = 180.0 / std::numbers::pi;

[[noreturn]] void arithmetic_error(uint32_t column, const std::string& what) {
  throw LineError(14051, column, what);
}

double checked(double v, uint32_t column) {
  if (!std::isfinite(v)) arithmetic_error(column, "result is not a finite number");
  return v;
}

bool truth(double v) { return v != 0.0; }

class Evaluator {
 public:
  Evaluator(const ExprPool& pool, const VariableSource& vars) : pool_(pool), vars_(vars) {}

  double eval(ExprIndex i) const {
    const ExprNode& n = pool_[i];
    switch (n.op) {
      case ExprOp::Number: return n.value;
      case ExprOp::String:
        throw LineError(12150, n.column, "a string is not allowed in a numeric expression");
      case ExprOp::Name: return vars_.variable(n.text, n.column);
      case ExprOp::RParam: return vars_.r_parameter(n.value, n.column);
      case ExprOp::RParamIndex: return vars_.r_parameter(eval(n.a), n.column);
      case ExprOp::Negate: return -eval(n.a);
      case ExprOp::Not: return truth(eval(n.a)) ? 0.0 : 1.0;
      case ExprOp::Add: return checked(eval(n.a) + eval(n.b), n.column);
      case ExprOp::Subtract: return checked(eval(n.a) - eval(n.b), n.column);
      case ExprOp::Multiply: return checked(eval(n.a) * eval(n.b), n.column);
      case ExprOp::Divide: {
        const double num = eval(n.a), den = eval(n.b);
        if (den == 0.0) arithmetic_error(n.column, "division by zero");
        return checked(num / den, n.column);
      }
      case ExprOp::IntDivide: {  // DIV: integer division, truncated towards zero
        const double num = std::trunc(eval(n.a)), den = std::trunc(eval(n.b));
        if (den == 0.0) arithmetic_error(n.column, "division by zero");
        return std::trunc(num / den);
      }
      case ExprOp::Modulo: {
        const double num = eval(n.a), den = eval(n.b);
        if (den == 0.0) arithmetic_error(n.column, "MOD by zero");
        return std::fmod(num, den);
      }
      case ExprOp::Equal: return eval(n.a) == eval(n.b) ? 1.0 : 0.0;
      case ExprOp::NotEqual: return eval(n.a) != eval(n.b) ? 1.0 : 0.0;
      case ExprOp::Less: return eval(n.a) < eval(n.b) ? 1.0 : 0.0;
      case ExprOp::Greater: return eval(n.a) > eval(n.b) ? 1.0 : 0.0;
      case ExprOp::LessEqual: return eval(n.a) <= eval(n.b) ? 1.0 : 0.0;
      case ExprOp::GreaterEqual: return eval(n.a) >= eval(n.b) ? 1.0 : 0.0;
      case ExprOp::And: return (truth(eval(n.a)) & truth(eval(n.b))) ? 1.0 : 0.0;
      case ExprOp::Or: return (truth(eval(n.a)) | truth(eval(n.b))) ? 1.0 : 0.0;
      case ExprOp::Xor: return (truth(eval(n.a)) != truth(eval(n.b))) ? 1.0 : 0.0;
      case ExprOp::Call: return call(n);
    }
    return 0.0;
  }

 private:
  double arg(const ExprNode& n, uint32_t k) const { return eval(pool_.args[n.a + k]); }

  double call(const ExprNode& n) const {
    const double x = arg(n, 0);
    switch (n.func) {
      case Function::Sin: return std::sin(x * kDegToRad);
      case Function::Cos: return std::cos(x * kDegToRad);
      case Function::Tan: {
        const double c = std::cos(x * kDegToRad);
        if (std::fabs(c) < 1e-15) arithmetic_error(n.column, "TAN of an odd multiple of 90 degrees");
        return std::sin(x * kDegToRad) / c;
      }
      case Function::Asin:
        if (x < -1.0 || x > 1.0) arithmetic_error(n.column, "ASIN argument outside [-1, 1]");
        return std::asin(x) * kRadToDeg;
      case Function::Acos:
        if (x < -1.0 || x > 1.0) arithmetic_error(n.column, "ACOS argument outside [-1, 1]");
        return std::acos(x) * kRadToDeg;
      case Function::Atan2: {
        const double xx = arg(n, 1);
        if (x == 0.0 && xx == 0.0) arithmetic_error(n.column, "ATAN2(0,0) is undefined");
        return std::atan2(x, xx) * kRadToDeg;
      }
      case Function::Sqrt:
        if (x < 0.0) arithmetic_error(n.column, "SQRT of a negative number");
        return std::sqrt(x);
      case Function::Abs: return std::fabs(x);
      case Function::Pot:  // POT(x) = x squared; POT(x, y) = x to the power y
        return n.b == 1 ? checked(x * x, n.column) : checked(std::pow(x, arg(n, 1)), n.column);
      case Function::Trunc: return std::trunc(x);
      case Function::Round: return std::round(x);  // halves away from zero
      case Function::Ln:
        if (x <= 0.0) arithmetic_error(n.column, "LN of a number <= 0");
        return std::log(x);
      case Function::Exp: return checked(std::exp(x), n.column);
      case Function::Min: return std::fmin(x, arg(n, 1));
      case Function::Max: return std::fmax(x, arg(n, 1));
      case Function::AbsoluteMode:
      case Function::IncrementalMode:
        throw LineError(12080, n.column, "AC()/IC() only allowed as the whole value of an address");
    }
    return 0.0;
  }

  const ExprPool& pool_;
  const VariableSource& vars_;
};

}  // namespace

double evaluate(const ExprPool& pool, ExprIndex root, const VariableSource& vars) {
  return Evaluator(pool, vars).eval(root);
}

}  // namespace drycut::parser
