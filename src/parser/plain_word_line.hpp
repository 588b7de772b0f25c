#pragma once
// The line parser's fast path for the lines CAM programs consist of: an optional block number
// and words of one address letter with a number, "N10 G1 X12.5 Y-3 F1500" (a ';' comment may
// follow). Such a line is read straight from its characters into the ParsedLine that the lexer
// and LineParser's general path give it: the same items in the same order, the same pool nodes
// (values, columns, texts), the same views into the upper-case copy, the same block number and
// statement column. Every other line is left to the general path: a name of two or more letters
// (SOFT, CR=, CYCLE832), any of = ( ) [ ] : / " ' $ _ and other operators, a blank between
// letter and number ("X 12"), an EX exponent, more than 15 digits, L/P/N/R words after the
// head, a G or M word written with a point or a sign. Those shapes have rules and alarms of their
// own, which only the general path knows.
#include <string_view>

#include "parser/parsed_line.hpp"

namespace drycut::parser {

// Parses the upper-case line `upper` into `out` when it has the plain-word shape above and
// returns true; otherwise returns false, `out` holding a partial result that the caller clears
// (statement_column and number_column, which ParsedLine::clear keeps, are as before the call).
bool parse_plain_word_line(std::string_view upper, ParsedLine& out);

}  // namespace drycut::parser
