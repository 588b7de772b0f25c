#include "parser/expression_api.hpp"

#include <vector>

#include "machine/alarm.hpp"
#include "parser/ascii_case.hpp"
#include "parser/expression_evaluator.hpp"
#include "parser/expression_parser.hpp"
#include "parser/lexer.hpp"
#include "parser/line_error.hpp"

namespace drycut::parser {
namespace {

class MapVariables : public VariableSource {
 public:
  explicit MapVariables(const std::map<std::string, double>& vars) {
    for (const auto& [k, v] : vars) upper_vars_[upper_ascii(k)] = v;
  }
  Value variable(std::string_view name, std::span<const Value> indices, uint32_t column) const override {
    if (indices.empty()) {
      if (auto it = upper_vars_.find(std::string(name)); it != upper_vars_.end()) return Value(it->second);
      if (name == "TRUE") return Value(1.0);
      if (name == "FALSE") return Value(0.0);
    }
    throw LineError(12550, column, "name " + std::string(name) + " not defined");
  }
  double r_parameter(double, uint32_t) const override { return 0.0; }

 private:
  std::map<std::string, double> upper_vars_;
};

}  // namespace

double evaluate_expression(std::string_view text, const std::map<std::string, double>& vars) {
  try {
    Lexer lexer;
    std::vector<Token> tokens;
    lexer.tokenize(text, tokens);
    ExprPool pool;
    size_t pos = 0;
    const ExprIndex root = ExpressionParser(tokens, pos, pool).parse();
    if (tokens[pos].kind != TokenKind::End)
      throw LineError(12080, tokens[pos].column, "unexpected '" + std::string(tokens[pos].text) + "'");
    return evaluate(pool, root, MapVariables(vars));
  } catch (const LineError& e) {
    throw AlarmError(make_alarm(e.number(), e.detail(), SourceLocation{"<expression>", 1, e.column()},
                                std::string(text)));
  }
}

}  // namespace drycut::parser
