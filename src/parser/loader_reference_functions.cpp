// Predefined functions whose arguments are not all values (Scope::reference_function):
// CALCDAT, which reads and writes whole arrays, and the valid functions drycut does not
// compute (Function::Assumed), which answer the result a call that went well gives, with
// warning 990002 naming the function and that value.
#include <array>
#include <cmath>
#include <vector>

#include "parser/circle_data.hpp"
#include "parser/expression_evaluator.hpp"
#include "parser/function_table.hpp"
#include "parser/line_error.hpp"
#include "parser/loader_frame.hpp"

namespace drycut::parser {

Value ProgramLoader::Scope::reference_function(const ExprNode& call, const ExprPool& pool) const {
  if (call.func == Function::CircleData) return circle_data(call, pool);
  const FunctionInfo* f = find_function(call.text);
  if (f == nullptr || f->func != Function::Assumed) return VariableSource::reference_function(call, pool);
  if (f->assumed.starts_with('#')) {  // "#n": the value of argument n
    const uint32_t k = static_cast<uint32_t>(f->assumed[1] - '1');
    if (k >= call.b) throw LineError(12080, call.column, std::string(f->name) + ": argument missing");
    const Value v = evaluate_value(pool, pool.args[call.a + k], *this);
    loader_.warn(990002, std::string(f->name) + "(): result not computed, its argument " +
                             std::string(f->assumed.substr(1)) + " (" + as_text(v) + ") taken",
                 call.column);
    return v;
  }
  const std::string assumed = f->assumed == "FRAME" ? "the null frame" : std::string(f->assumed);
  loader_.warn(990002, std::string(f->name) + "(): result not computed, " + assumed + " taken", call.column);
  return assumed_result(*f);
}

// CALCDAT(PT, NUM, RES): PT a REAL array [n, 2] of points, NUM = 3 or 4 of them are used, RES a
// REAL array [3] that receives centre abscissa, ordinate and radius (Job Planning, "Calculate
// circle data (CALCDAT)"). RES is left as it was when the points give no circle.
Value ProgramLoader::Scope::circle_data(const ExprNode& call, const ExprPool& pool) const {
  auto array_argument = [&](uint32_t k) -> Variable& {
    const ExprNode& a = pool[pool.args[call.a + k]];
    Variable* v = a.op == ExprOp::Name && a.b == 0 ? loader_.find_variable(a.text) : nullptr;
    if (v == nullptr || !is_numeric_type(v->type()))
      throw LineError(12150, a.column, "CALCDAT needs the name of a REAL array here");
    return *v;
  };
  Variable& points = array_argument(0);
  const double count = evaluate(pool, pool.args[call.a + 1], *this);
  Variable& result = array_argument(2);
  if (count != 3 && count != 4) throw LineError(12150, call.column, "CALCDAT uses 3 or 4 points");
  if (points.rank() != 2 || points.dim(1) < 2 || points.dim(0) < count)
    throw LineError(17020, call.column, "CALCDAT: " + points.name() + " must hold " + number_to_text(count) +
                                            " points of 2 coordinates ([n, 2])");
  if (result.size() < 3) throw LineError(17020, call.column, "CALCDAT: " + result.name() + " must hold 3 values");
  std::vector<std::array<double, 2>> xy(static_cast<size_t>(count));
  for (size_t i = 0; i < xy.size(); ++i)
    for (size_t c = 0; c < 2; ++c) {
      const std::array<Value, 2> index{Value(static_cast<double>(i)), Value(static_cast<double>(c))};
      xy[i][c] = points.get(points.element(index, call.column)).number;
    }
  const auto circle = circle_through_points(xy);
  if (!circle) return Value(0.0);
  result.set(0, Value(circle->centre_x), call.column);
  result.set(1, Value(circle->centre_y), call.column);
  result.set(2, Value(circle->radius), call.column);
  return Value(1.0);
}

}  // namespace drycut::parser
