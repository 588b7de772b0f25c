#pragma once
// Evaluates expression trees. Angles are in degrees (SINUMERIK); arithmetic errors (division
// by zero, SQRT of a negative number, ...) raise LineError 14051 at the operator's column, a
// string where a number is needed (or the reverse) 12150.
//
// REAL comparison: ==, <>, <=, >= treat two values as equal when they differ by at most
// 1e-12 of the larger magnitude, as the control does by default (MD10280
// PROG_FUNCTION_MASK bit 0 = 0; PGA "Comparison and logical operations"), so that
// 0.1+0.2==0.3 is TRUE on the control and here.
#include <span>
#include <string_view>

#include "parser/expression.hpp"
#include "parser/value.hpp"

namespace drycut::parser {

// Supplies the values of names; throws LineError 12550 for an unknown name.
class VariableSource {
 public:
  virtual ~VariableSource() = default;
  // A variable, a $ system variable or a bare axis name with its evaluated indices (empty when
  // written without [ ]).
  virtual Value variable(std::string_view upper_name, std::span<const Value> indices, uint32_t column) const = 0;
  virtual double r_parameter(double index, uint32_t column) const = 0;
  // Functions answered by the program's environment: ISVAR, GETT, the frame functions.
  virtual Value environment_function(const ExprNode& call, std::span<const Value> args) const;
  // Functions whose arguments are not (all) values: CALCDAT reads and writes arrays named by its
  // arguments, an assumed function (Function::Assumed) evaluates none of them (they may be
  // VAR results). `pool` holds the call's argument nodes.
  virtual Value reference_function(const ExprNode& call, const ExprPool& pool) const;
};

Value evaluate_value(const ExprPool& pool, ExprIndex root, const VariableSource& vars);
// A number; a text result is alarm 12150.
double evaluate(const ExprPool& pool, ExprIndex root, const VariableSource& vars);

// The numeric value of a Value, or LineError 12150 at `column`.
double as_number(const Value& v, uint32_t column);
// The text `<<` makes of a value.
std::string as_text(const Value& v);
// Equality as the control compares REAL values (relative tolerance, see above).
bool real_equal(double a, double b);

}  // namespace drycut::parser
