#pragma once
// The string functions of the NC language (PGA Job Planning, "String operations"): STRLEN,
// INDEX, RINDEX, MINDEX, SUBSTR, TOUPPER, TOLOWER, NUMBER, ISNUMBER, SPRINT, AXNAME, AXSTRING.
// Positions count from 0; a character that is not found gives -1.
#include <span>

#include "parser/expression.hpp"
#include "parser/value.hpp"

namespace drycut::parser {

// Throws LineError 12150 for an argument of the wrong type, 14051 for NUMBER of a text that is
// not a number.
Value string_function(Function f, std::span<const Value> args, uint32_t column);

// SPRINT's formatting: %D/%I integer, %F real (6 decimals, %.nF n decimals), %E exponent,
// %S string, %C character, %B TRUE/FALSE, %X hexadecimal, %% a percent sign.
std::string sprint(std::span<const Value> args, uint32_t column);

}  // namespace drycut::parser
