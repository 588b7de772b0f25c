#pragma once
// Appending JSON text by hand, for writers that stream millions of rows: a number rounded to a
// fixed count of decimals (std::to_chars, no locale, no allocation) and an escaped string.
// JSON has no NaN or infinity: those are written as null.
#include <string>
#include <string_view>

namespace drycut::report {

// `value` rounded to `decimals` places, trailing zeros dropped ("1500", "0.0123457", "-2.5").
void append_json_number(std::string& out, double value, int decimals);
void append_json_integer(std::string& out, unsigned long long value);
// `"text"` with quotes, backslashes and control characters escaped; invalid UTF-8 bytes are
// replaced by U+FFFD (block texts come from shop files).
void append_json_string(std::string& out, std::string_view text);

}  // namespace drycut::report
