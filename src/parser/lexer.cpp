#include "parser/lexer.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <string>
#include <utility>

#include "parser/ascii_case.hpp"
#include "parser/line_error.hpp"
#include "parser/plain_decimal.hpp"

namespace drycut::parser {
namespace {

inline bool is_digit(char c) { return c >= '0' && c <= '9'; }
inline bool is_name_start(char c) {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_' || c == '$';
}
inline bool is_name_char(char c) { return is_name_start(c) || is_digit(c); }

std::string describe_char(char c) {
  const auto b = static_cast<unsigned char>(c);
  if (b >= 0x21 && b < 0x7F) return std::string("invalid character '") + c + "'";
  char buf[32];
  std::snprintf(buf, sizeof buf, "invalid byte 0x%02X", b);
  return buf;
}

// Scans digits [. digits] [EX [+|-] digits] starting at i; returns the end. EX is the power
// of ten (PGA Fundamentals, "Arithmetic parameters": R1=1.874EX8 is 187400000).
size_t scan_number(std::string_view s, size_t i) {
  while (i < s.size() && is_digit(s[i])) ++i;
  if (i < s.size() && s[i] == '.') {
    ++i;
    while (i < s.size() && is_digit(s[i])) ++i;
  }
  if (i + 2 < s.size() && s[i] == 'E' && s[i + 1] == 'X') {
    size_t j = i + 2;
    if (s[j] == '+' || s[j] == '-') ++j;
    if (j < s.size() && is_digit(s[j])) {
      while (j < s.size() && is_digit(s[j])) ++j;
      i = j;
    }
  }
  return i;
}

// The whole text a plain decimal of at most 15 digits: its value, else false.
bool fast_decimal(std::string_view digits, double& out) {
  const PlainDecimal d = scan_plain_decimal(digits, 0);
  if (d.end != digits.size() || !d.exact()) return false;
  out = d.value();
  return true;
}

double to_double(std::string_view text, uint32_t column) {
  if (double v = 0.0; fast_decimal(text, v)) return v;
  if (const size_t ex = text.find("EX"); ex != std::string_view::npos) {  // mantissa EX exponent
    const double mantissa = to_double(text.substr(0, ex), column);
    const std::string_view power = text.substr(ex + 2);
    int e = 0;
    const bool negative = power.front() == '-';
    const std::string_view digits = power.substr(power.front() == '+' || negative ? 1 : 0);
    std::from_chars(digits.data(), digits.data() + digits.size(), e);
    return mantissa * std::pow(10.0, negative ? -e : e);
  }
  double v = 0.0;
  // "5." is valid NC: from_chars stops before a lone trailing dot, so parse without it.
  std::string_view digits = text;
  if (!digits.empty() && digits.back() == '.') digits.remove_suffix(1);
  if (digits.empty() || digits == ".") throw LineError(12080, column, "malformed number");
  const auto r = std::from_chars(digits.data(), digits.data() + digits.size(), v);
  if (r.ec != std::errc() || r.ptr != digits.data() + digits.size())
    throw LineError(12080, column, "malformed number '" + std::string(text) + "'");
  return v;
}

inline uint32_t col(size_t pos) { return static_cast<uint32_t>(pos + 1); }

inline void push(std::vector<Token>& out, std::string_view s, TokenKind k, size_t start, size_t len) {
  out.push_back(Token{k, col(start), s.substr(start, len), 0.0});
}

// The number starting at i as a Number token; returns its end. A plain decimal (digits with at
// most one point, no EX) is converted as it is scanned, to the value fast_decimal gives: the
// coordinates of a CAM program are read once instead of three times.
inline size_t lex_number(std::string_view s, size_t i, std::vector<Token>& out) {
  const PlainDecimal d = scan_plain_decimal(s, i);
  const bool plain = !exponent_follows(s, d.end);
  const size_t end = plain ? d.end : scan_number(s, i);
  Token t{TokenKind::Number, col(i), s.substr(i, end - i), 0.0};
  t.number = plain && d.exact() ? d.value() : to_double(t.text, t.column);
  out.push_back(t);
  return end;
}

// A name or an address word starting at i (a name-start character); returns its end.
inline size_t lex_name(std::string_view s, size_t i, std::vector<Token>& out) {
  const size_t n = s.size();
  const size_t start = i;
  if (s[i] == '$') ++i;  // system variables: $AA_IM, $P_TOOL
  while (i < n && ((s[i] >= 'A' && s[i] <= 'Z') || s[i] == '_')) ++i;
  const size_t letters_end = i;
  while (i < n && is_digit(s[i])) ++i;
  if (letters_end - start == 1 && i > letters_end) {
    // The address rule (PGA "Identifiers": names of variables and programs begin with two
    // letters or an underscore): one letter followed by a digit is an address word. It
    // ends with its digits, so compact blocks read as the control reads them:
    // "N10G1X10Y20" is N10 G1 X10 Y20, "S12M3" is S12 M3.
    // "X12.345" and "X1EX2" (with its power of ten: 100, as "X1.0EX2"): the letter, then a
    // decimal number. EX followed by digits is read as the exponent, not as a call of a
    // program EX2 glued to the value.
    if (i < n && (s[i] == '.' || (exponent_follows(s, i) && scan_number(s, letters_end) > i))) {
      push(out, s, TokenKind::Name, start, 1);
      return lex_number(s, letters_end, out);
    }
    push(out, s, TokenKind::Name, start, i - start);  // "X10", "G1", "R5", "L12", "X1" of X1=
    return i;
  }
  while (i < n && is_name_char(s[i])) ++i;
  // A program name may carry its extension: EKVI_POSTUPNE_45.SPF
  if (i + 4 <= n && s[i] == '.' && (s.substr(i + 1, 3) == "SPF" || s.substr(i + 1, 3) == "MPF") &&
      (i + 4 == n || !is_name_char(s[i + 4])))
    i += 4;
  push(out, s, TokenKind::Name, start, i - start);
  return i;
}

// A string starting at the '"' at i; returns the position after its closing '"'.
inline size_t lex_string(std::string_view line, size_t i, std::vector<Token>& out) {
  const size_t close = line.find('"', i + 1);
  if (close == std::string_view::npos) throw LineError(12080, col(i), "unterminated string (missing \")");
  // Strings keep their case: take them from the original line.
  out.push_back(Token{TokenKind::String, col(i), line.substr(i + 1, close - i - 1), 0.0});
  return close + 1;
}

// 'H1F' hexadecimal, 'B101' binary constants, starting at the quote at i; returns their end.
inline size_t lex_based_constant(std::string_view s, size_t i, std::vector<Token>& out) {
  const size_t close = s.find('\'', i + 1);
  if (close == std::string_view::npos || close < i + 3)
    throw LineError(12080, col(i), "unterminated or empty constant (missing ')");
  const int base = s[i + 1] == 'H' ? 16 : s[i + 1] == 'B' ? 2 : 0;
  uint64_t v = 0;
  const char* first = s.data() + i + 2;
  const char* last = s.data() + close;
  const auto r = base ? std::from_chars(first, last, v, base)
                      : std::from_chars_result{first, std::errc::invalid_argument};
  if (r.ec != std::errc() || r.ptr != last)
    throw LineError(12080, col(i), "malformed 'H..' or 'B..' constant");
  Token t{TokenKind::Number, col(i), s.substr(i, close + 1 - i), static_cast<double>(v)};
  out.push_back(t);
  return close + 1;
}

// An operator or a bracket at i: its kind and length (one or two characters). Anything else
// cannot start a token.
inline std::pair<TokenKind, size_t> operator_at(std::string_view s, size_t i) {
  const char c = s[i];
  const char next = i + 1 < s.size() ? s[i + 1] : '\0';
  switch (c) {
    case '(': return {TokenKind::LParen, 1};
    case ')': return {TokenKind::RParen, 1};
    case '[': return {TokenKind::LBracket, 1};
    case ']': return {TokenKind::RBracket, 1};
    case ',': return {TokenKind::Comma, 1};
    case '+': return {TokenKind::Plus, 1};
    case '-': return {TokenKind::Minus, 1};
    case '*': return {TokenKind::Star, 1};
    case '/': return {TokenKind::Slash, 1};
    case ':': return {TokenKind::Colon, 1};
    case '=':
      if (next == '=') return {TokenKind::Equal, 2};
      return {TokenKind::Assign, 1};
    case '<':
      if (next == '>') return {TokenKind::NotEqual, 2};
      if (next == '=') return {TokenKind::LessEqual, 2};
      if (next == '<') return {TokenKind::Concat, 2};
      return {TokenKind::Less, 1};
    case '>':
      if (next == '=') return {TokenKind::GreaterEqual, 2};
      return {TokenKind::Greater, 1};
    default:
      throw LineError(12080, col(i), describe_char(c));
  }
}

}  // namespace

std::string_view Lexer::upper_case(std::string_view line) {
  upper_.assign(line);
  to_upper_ascii(upper_);
  return upper_;
}

void Lexer::tokenize(std::string_view line, std::vector<Token>& out) {
  upper_case(line);
  tokenize_upper_cased(line, out);
}

void Lexer::tokenize_upper_cased(std::string_view line, std::vector<Token>& out) {
  out.clear();
  const std::string_view s = upper_;
  const size_t n = s.size();
  size_t i = 0;
  while (i < n) {
    const char c = s[i];
    if (is_lexer_blank(c)) {
      ++i;
      continue;
    }
    if (c == ';') break;  // comment to end of line
    if (is_name_start(c))
      i = lex_name(s, i, out);
    else if (is_digit(c) || (c == '.' && i + 1 < n && is_digit(s[i + 1])))
      i = lex_number(s, i, out);  // a name may follow directly: "X.5Y2" is X.5 Y2
    else if (c == '"')
      i = lex_string(line, i, out);
    else if (c == '\'')
      i = lex_based_constant(s, i, out);
    else {
      // operator_at only classifies: with a push per operator case GCC no longer inlined push().
      const auto [kind, length] = operator_at(s, i);
      push(out, s, kind, i, length);
      i += length;
    }
  }
  out.push_back(Token{TokenKind::End, col(i), std::string_view(), 0.0});
}

}  // namespace drycut::parser
