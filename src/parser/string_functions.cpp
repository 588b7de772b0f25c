#include "parser/string_functions.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <string>

#include "parser/ascii_case.hpp"
#include "parser/expression_evaluator.hpp"
#include "parser/line_error.hpp"

namespace drycut::parser {
namespace {

const std::string& text_arg(std::span<const Value> args, size_t k, uint32_t column) {
  if (k >= args.size() || args[k].is_number())
    throw LineError(12150, column, "a string argument is needed");
  return args[k].text;
}

// A character code as a char; a value no int holds is no character (its cast would be undefined).
char char_of_code(double code, uint32_t column) {
  if (!(code > -2147483648.0 && code < 2147483648.0)) throw LineError(12160, column, "character code out of range");
  return static_cast<char>(static_cast<int>(code));
}

// A character argument: a one-character string or a character code.
char char_arg(std::span<const Value> args, size_t k, uint32_t column) {
  if (k < args.size() && args[k].is_number()) return char_of_code(args[k].number, column);
  const std::string& s = text_arg(args, k, column);
  if (s.empty()) throw LineError(12150, column, "a character is needed");
  return s[0];
}

// The number a text holds, as the control reads numbers ("12", "-1.5", " 3 "), with a power of
// ten written EX as in a program ("1234.9876Ex-7", Job Planning's NUMBER/ISNUMBER example).
bool parse_number(const std::string& text, double& out) {
  size_t b = 0, e = text.size();
  while (b < e && text[b] == ' ') ++b;
  while (e > b && text[e - 1] == ' ') --e;
  if (b == e) return false;
  std::string digits = text.substr(b, e - b);
  const size_t ex = upper_ascii(digits).find("EX");
  if (ex != std::string::npos) digits.erase(ex + 1, 1);  // "EX" -> "E": from_chars' exponent
  const char* first = digits.data();
  const char* last = first + digits.size();
  if (*first == '+') ++first;
  const auto r = std::from_chars(first, last, out);
  return r.ec == std::errc() && r.ptr == last && std::isfinite(out);
}

std::string lower_ascii(std::string s) {
  for (char& c : s)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return s;
}

}  // namespace

Value string_function(Function f, std::span<const Value> args, uint32_t column) {
  switch (f) {
    case Function::StrLen: return Value(static_cast<double>(text_arg(args, 0, column).size()));
    case Function::Index: {
      const auto p = text_arg(args, 0, column).find(char_arg(args, 1, column));
      return Value(p == std::string::npos ? -1.0 : static_cast<double>(p));
    }
    case Function::RIndex: {
      const auto p = text_arg(args, 0, column).rfind(char_arg(args, 1, column));
      return Value(p == std::string::npos ? -1.0 : static_cast<double>(p));
    }
    case Function::Match: {  // MATCH(s, part): first position of the string part, -1 if none
      const auto p = text_arg(args, 0, column).find(text_arg(args, 1, column));
      return Value(p == std::string::npos ? -1.0 : static_cast<double>(p));
    }
    case Function::MIndex: {
      const auto p = text_arg(args, 0, column).find_first_of(text_arg(args, 1, column));
      return Value(p == std::string::npos ? -1.0 : static_cast<double>(p));
    }
    case Function::SubStr: {
      const std::string& s = text_arg(args, 0, column);
      const double start = as_number(args[1], column);
      const double count = args.size() > 2 ? as_number(args[2], column) : static_cast<double>(s.size());
      if (start < 0 || count < 0) throw LineError(12150, column, "SUBSTR: negative position or length");
      if (start >= static_cast<double>(s.size())) return Value::of_text("");
      return Value::of_text(s.substr(static_cast<size_t>(start), static_cast<size_t>(std::fmin(count, 1e9))));
    }
    case Function::ToUpper: return Value::of_text(upper_ascii(text_arg(args, 0, column)));
    case Function::ToLower: return Value::of_text(lower_ascii(text_arg(args, 0, column)));
    case Function::Number: {
      double v = 0;
      if (!parse_number(text_arg(args, 0, column), v))
        throw LineError(14051, column, "NUMBER: \"" + args[0].text + "\" is not a number");
      return Value(v);
    }
    case Function::IsNumber: {
      double v = 0;
      return Value(parse_number(text_arg(args, 0, column), v) ? 1.0 : 0.0);
    }
    case Function::Sprint: return Value::of_text(sprint(args, column));
    case Function::AxName: return Value::of_axis(upper_ascii(text_arg(args, 0, column)));
    case Function::AxString:
      if (args.empty() || args[0].kind != ValueKind::Axis) throw LineError(12150, column, "AXSTRING needs an axis");
      return Value::of_text(args[0].text);
    default: throw LineError(12550, column, "not a string function");
  }
}

std::string sprint(std::span<const Value> args, uint32_t column) {
  const std::string& format = text_arg(args, 0, column);
  std::string out;
  size_t next = 1;
  auto take = [&]() -> const Value& {
    if (next >= args.size()) throw LineError(12150, column, "SPRINT: more formats than values");
    return args[next++];
  };
  char buf[400];  // %.20F of the largest double: 309 digits, point, 20 decimals, sign
  for (size_t i = 0; i < format.size(); ++i) {
    if (format[i] != '%' || i + 1 == format.size()) {
      out += format[i];
      continue;
    }
    ++i;
    // %<width>.<decimals>F: a field width pads on the left with blanks (Job Planning, SPRINT).
    size_t width = 0;
    while (i < format.size() && format[i] >= '0' && format[i] <= '9') width = std::min<size_t>(width * 10 + static_cast<size_t>(format[i++] - '0'), 200);
    if (i >= format.size()) break;
    const size_t field_start = out.size();
    int decimals = 6;
    bool precision = false;  // %.3S takes 3 characters of the string
    if (format[i] == '.') {  // %.3F
      precision = true;
      decimals = 0;
      while (i + 1 < format.size() && format[i + 1] >= '0' && format[i + 1] <= '9')
        decimals = std::min(decimals * 10 + (format[++i] - '0'), 200);  // no int overflow
      ++i;
      if (i >= format.size()) break;
    }
    const int digits = std::min(decimals, 20);  // of a number (a string may take up to 200 characters)
    switch (format[i] & ~0x20) {  // upper case
      case 'D':
      case 'I': std::snprintf(buf, sizeof buf, "%lld", static_cast<long long>(std::llround(as_number(take(), column)))); out += buf; break;
      case 'F': std::snprintf(buf, sizeof buf, "%.*f", digits, as_number(take(), column)); out += buf; break;
      case 'E': std::snprintf(buf, sizeof buf, "%.*E", digits, as_number(take(), column)); out += buf; break;
      // %.nG: decimal or exponential by the value's range, n significant digits (as C's %G).
      case 'G': std::snprintf(buf, sizeof buf, "%.*G", digits, as_number(take(), column)); out += buf; break;
      case 'X': std::snprintf(buf, sizeof buf, "%llX", static_cast<unsigned long long>(std::llround(as_number(take(), column)))); out += buf; break;
      case 'B': out += as_number(take(), column) != 0.0 ? "TRUE" : "FALSE"; break;
      case 'C': out += char_of_code(as_number(take(), column), column); break;
      case 'S': {
        const std::string text = as_text(take());
        out += precision ? text.substr(0, static_cast<size_t>(decimals)) : text;
        break;
      }
      default:
        if (format[i] == '%') out += '%';
        else throw LineError(12150, column, std::string("SPRINT: unknown format %") + format[i]);
    }
    if (const size_t written = out.size() - field_start; written < width) out.insert(field_start, width - written, ' ');
  }
  return out;
}

}  // namespace drycut::parser
