#include "parser/expression_evaluator.hpp"

#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

#include "parser/line_error.hpp"
#include "parser/string_functions.hpp"

namespace drycut::parser {
namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;
constexpr double kRadToDeg = 180.0 / std::numbers::pi;
constexpr double kRealCompareTolerance = 1e-12;

[[noreturn]] void arithmetic_error(uint32_t column, const std::string& what) {
  throw LineError(14051, column, what);
}

double checked(double v, uint32_t column) {
  if (!std::isfinite(v)) arithmetic_error(column, "result is not a finite number");
  return v;
}

bool truth(double v) { return v != 0.0; }

int64_t as_bits(double v, uint32_t column) {
  if (!(std::fabs(v) < 9.0e18)) arithmetic_error(column, "value too large for a bit operation");
  return static_cast<int64_t>(std::llround(v));
}

class Evaluator {
 public:
  Evaluator(const ExprPool& pool, const VariableSource& vars) : pool_(pool), vars_(vars) {}

  Value eval(ExprIndex i) const {
    const ExprNode& n = pool_[i];
    switch (n.op) {
      case ExprOp::Number: return Value(n.value);
      case ExprOp::String: return Value::of_text(std::string(n.text));
      case ExprOp::Name: return name(n);
      case ExprOp::Call: return call(n);
      case ExprOp::Concat: return Value::of_text(as_text(eval(n.a)) + as_text(eval(n.b)));
      case ExprOp::FrameChain: {
        Value a = eval(n.a);
        const Value b = eval(n.b);
        if (a.kind != ValueKind::Frame || b.kind != ValueKind::Frame)
          throw LineError(12150, n.column, "':' chains FRAME values only");
        a.text += ':';
        a.text += b.text;
        return a;
      }
      case ExprOp::Equal:
      case ExprOp::NotEqual:
      case ExprOp::Less:
      case ExprOp::Greater:
      case ExprOp::LessEqual:
      case ExprOp::GreaterEqual: return Value(compare(n) ? 1.0 : 0.0);
      default: return Value(number(i));
    }
  }

  double number(ExprIndex i) const {
    const ExprNode& n = pool_[i];
    switch (n.op) {
      case ExprOp::Number: return n.value;
      case ExprOp::RParam: return vars_.r_parameter(n.value, n.column);
      case ExprOp::RParamIndex: return vars_.r_parameter(number(n.a), n.column);
      case ExprOp::Negate: return -number(n.a);
      case ExprOp::Not: return truth(number(n.a)) ? 0.0 : 1.0;
      case ExprOp::BitNot: return static_cast<double>(~as_bits(number(n.a), n.column));
      case ExprOp::Add: return checked(number(n.a) + number(n.b), n.column);
      case ExprOp::Subtract: return checked(number(n.a) - number(n.b), n.column);
      case ExprOp::Multiply: return checked(number(n.a) * number(n.b), n.column);
      case ExprOp::Divide: {
        const double num = number(n.a), den = number(n.b);
        if (den == 0.0) arithmetic_error(n.column, "division by zero");
        return checked(num / den, n.column);
      }
      case ExprOp::IntDivide: {  // DIV: integer division, truncated towards zero
        const double num = std::trunc(number(n.a)), den = std::trunc(number(n.b));
        if (den == 0.0) arithmetic_error(n.column, "division by zero");
        return std::trunc(num / den);
      }
      case ExprOp::Modulo: {
        const double num = number(n.a), den = number(n.b);
        if (den == 0.0) arithmetic_error(n.column, "MOD by zero");
        return std::fmod(num, den);
      }
      case ExprOp::And: return (truth(number(n.a)) & truth(number(n.b))) ? 1.0 : 0.0;
      case ExprOp::Or: return (truth(number(n.a)) | truth(number(n.b))) ? 1.0 : 0.0;
      case ExprOp::Xor: return (truth(number(n.a)) != truth(number(n.b))) ? 1.0 : 0.0;
      case ExprOp::BitAnd: return static_cast<double>(as_bits(number(n.a), n.column) & as_bits(number(n.b), n.column));
      case ExprOp::BitOr: return static_cast<double>(as_bits(number(n.a), n.column) | as_bits(number(n.b), n.column));
      case ExprOp::BitXor: return static_cast<double>(as_bits(number(n.a), n.column) ^ as_bits(number(n.b), n.column));
      default: return as_number(eval(i), n.column);
    }
  }

 private:
  Value name(const ExprNode& n) const {
    if (n.b == 0) return vars_.variable(n.text, {}, n.column);
    Value idx[3];
    for (uint32_t k = 0; k < n.b && k < 3; ++k) idx[k] = eval(pool_.args[n.a + k]);
    return vars_.variable(n.text, std::span<const Value>(idx, n.b), n.column);
  }

  bool compare(const ExprNode& n) const {
    Value a = eval(n.a), b = eval(n.b);
    // A CHAR is a number (its code); compared with a one-character string it compares codes.
    auto one_char_code = [](Value& v) {
      if (v.is_text() && v.text.size() == 1) v = Value(static_cast<unsigned char>(v.text[0]));
    };
    if (a.is_number() && b.is_text()) one_char_code(b);
    if (b.is_number() && a.is_text()) one_char_code(a);
    if (!a.is_number() || !b.is_number()) {
      if (a.is_number() != b.is_number())
        throw LineError(12150, n.column, "a string compared with a number");
      const int c = a.text.compare(b.text);
      switch (n.op) {
        case ExprOp::Equal: return c == 0;
        case ExprOp::NotEqual: return c != 0;
        case ExprOp::Less: return c < 0;
        case ExprOp::Greater: return c > 0;
        case ExprOp::LessEqual: return c <= 0;
        default: return c >= 0;
      }
    }
    const bool eq = real_equal(a.number, b.number);
    switch (n.op) {
      case ExprOp::Equal: return eq;
      case ExprOp::NotEqual: return !eq;
      case ExprOp::Less: return !eq && a.number < b.number;
      case ExprOp::Greater: return !eq && a.number > b.number;
      case ExprOp::LessEqual: return eq || a.number < b.number;
      default: return eq || a.number > b.number;
    }
  }

  double arg(const ExprNode& n, uint32_t k) const { return number(pool_.args[n.a + k]); }

  Value call(const ExprNode& n) const {
    switch (n.func) {
      case Function::StrLen: case Function::Index: case Function::RIndex: case Function::MIndex:
      case Function::SubStr: case Function::ToUpper: case Function::ToLower: case Function::Number:
      case Function::IsNumber: case Function::Sprint: case Function::AxName: case Function::AxString:
      case Function::Match:
      case Function::IsVar: case Function::IsFile: case Function::GetT: case Function::FrameFunction:
      case Function::StringIs: case Function::Spindle: case Function::NameToInt: {
        std::vector<Value> args;
        args.reserve(n.b);
        for (uint32_t k = 0; k < n.b; ++k) args.push_back(eval(pool_.args[n.a + k]));
        if (n.func == Function::IsVar || n.func == Function::IsFile || n.func == Function::GetT ||
            n.func == Function::FrameFunction || n.func == Function::StringIs || n.func == Function::Spindle ||
            n.func == Function::NameToInt)
          return vars_.environment_function(n, args);
        return string_function(n.func, args, n.column);
      }
      case Function::CircleData: case Function::Assumed: return vars_.reference_function(n, pool_);
      case Function::AbsoluteMode: case Function::IncrementalMode: case Function::DirectMode:
      case Function::AbsolutePositive: case Function::AbsoluteNegative: case Function::DiameterAbsolute:
      case Function::DiameterIncremental: case Function::RadiusAbsolute: case Function::RadiusIncremental:
      case Function::PerMinute: case Function::PerRevolution:
        throw LineError(12080, n.column, std::string(n.text) + "() only allowed as the whole value of an address");
      case Function::ArraySet: case Function::ArrayRep:
        throw LineError(12080, n.column, std::string(n.text) + "() only allowed as the whole value of an array element");
      default: return Value(arithmetic(n));
    }
  }

  double arithmetic(const ExprNode& n) const {
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
      case Function::RoundUp: return std::ceil(x);
      case Function::Ln:
        if (x <= 0.0) arithmetic_error(n.column, "LN of a number <= 0");
        return std::log(x);
      case Function::Exp: return checked(std::exp(x), n.column);
      case Function::Min: return std::fmin(x, arg(n, 1));
      case Function::Max: return std::fmax(x, arg(n, 1));
      case Function::ToReal: return x;
      case Function::ToInt: return std::round(x);  // REAL -> INT rounds, halves away from zero
      case Function::ToBool: return x != 0.0 ? 1.0 : 0.0;
      case Function::QuickOutput: return x;  // M=QU(8): M8, output without waiting (same path)
      case Function::IsAxis: return x >= 1 && x <= 3 ? 1.0 : 0.0;  // geometry axes 1..3 exist
      case Function::Bound: {  // BOUND(min, max, value)
        const double hi = arg(n, 1), v = arg(n, 2);
        if (x > hi) arithmetic_error(n.column, "BOUND: minimum greater than maximum");
        return std::fmin(std::fmax(v, x), hi);
      }
      default: return 0.0;
    }
  }

  const ExprPool& pool_;
  const VariableSource& vars_;
};

}  // namespace

Value VariableSource::environment_function(const ExprNode& call, std::span<const Value>) const {
  throw LineError(12550, call.column, "function " + std::string(call.text) + " not available here");
}

Value VariableSource::reference_function(const ExprNode& call, const ExprPool&) const {
  throw LineError(12550, call.column, "function " + std::string(call.text) + " not available here");
}

double as_number(const Value& v, uint32_t column) {
  if (!v.is_number())
    throw LineError(12150, column, v.is_text() ? "a string where a number is needed (\"" + v.text + "\")"
                                               : "an axis or frame where a number is needed");
  return v.number;
}

std::string as_text(const Value& v) {
  switch (v.kind) {
    case ValueKind::Number:
      // A CHAR's code as its character (a code outside 0..255, written as a number, as a number).
      if (v.character && v.number >= 0 && v.number <= 255)
        return std::string(1, static_cast<char>(static_cast<unsigned char>(v.number)));
      return number_to_text(v.number);
    case ValueKind::Frame: return "FRAME";
    default: return v.text;
  }
}

bool real_equal(double a, double b) {
  if (a == b) return true;
  return std::fabs(a - b) <= kRealCompareTolerance * std::fmax(std::fabs(a), std::fabs(b));
}

Value evaluate_value(const ExprPool& pool, ExprIndex root, const VariableSource& vars) {
  return Evaluator(pool, vars).eval(root);
}

double evaluate(const ExprPool& pool, ExprIndex root, const VariableSource& vars) {
  return Evaluator(pool, vars).number(root);
}

}  // namespace drycut::parser
