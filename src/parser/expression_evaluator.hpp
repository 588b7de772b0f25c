#pragma once
// Evaluates expression trees. Angles are in degrees (SINUMERIK); arithmetic errors (division
// by zero, SQRT of a negative number, ...) raise LineError 14051 at the operator's column.
#include <string_view>

#include "parser/expression.hpp"

namespace drycut::parser {

// Supplies the values of names; throws LineError 12550 for an unknown name.
class VariableSource {
 public:
  virtual ~VariableSource() = default;
  virtual double variable(std::string_view upper_name, uint32_t column) const = 0;
  virtual double r_parameter(double index, uint32_t column) const = 0;
};

double evaluate(const ExprPool& pool, ExprIndex root, const VariableSource& vars);

}  // namespace drycut::parser
