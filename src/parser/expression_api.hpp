#pragma once
// The NC expression engine for code outside the loader (e.g. the program generator evaluating
// a user curve such as "18+4*COS(6*T)*COS(2*T)"). Same grammar, precedence and degrees as in
// part programs.
#include <map>
#include <string>
#include <string_view>

namespace drycut::parser {

// Evaluates `text` with the given variables (names case-insensitive; R parameters are 0).
// Throws AlarmError (12080 syntax, 12550 unknown name, 14051 arithmetic) whose location is
// "<expression>", line 1, and the column in `text`.
double evaluate_expression(std::string_view text, const std::map<std::string, double>& vars);

}  // namespace drycut::parser
