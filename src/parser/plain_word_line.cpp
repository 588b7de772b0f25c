#include "parser/plain_word_line.hpp"

#include <cstdint>

#include "parser/lexer.hpp"
#include "parser/plain_decimal.hpp"

namespace drycut::parser {
namespace {

inline bool is_letter(char c) { return c >= 'A' && c <= 'Z'; }
inline bool is_digit(char c) { return c >= '0' && c <= '9'; }
inline uint32_t col(size_t pos) { return static_cast<uint32_t>(pos + 1); }

// Up to 15 digits from i: no saturation and an exact double, as the general path's integer.
constexpr size_t kMaxDigits = 15;

size_t skip_blanks(std::string_view s, size_t i) {
  while (i < s.size() && is_lexer_blank(s[i])) ++i;
  return i;
}

size_t digits_end(std::string_view s, size_t i) {
  while (i < s.size() && is_digit(s[i])) ++i;
  return i;
}

uint64_t digits_value(std::string_view digits) {
  uint64_t v = 0;
  for (const char c : digits) v = v * 10 + static_cast<uint64_t>(c - '0');
  return v;
}

// "G1", "M3", "X10": the letter and its digits are one token (not followed by a point), as the
// lexer's address rule reads them; LineParser::parse_letter_digits_word gives the item.
bool letter_digits_word(std::string_view s, size_t start, size_t end, Item& item, ParsedLine& out) {
  const std::string_view digits = s.substr(start + 1, end - start - 1);
  const uint64_t v = digits_value(digits);
  switch (s[start]) {
    case 'G': item.kind = ItemKind::G; item.code = static_cast<int64_t>(v); return true;
    case 'M': item.kind = ItemKind::M; item.code = static_cast<int64_t>(v); return true;
    case 'L': case 'P': case 'N': case 'R': return false;  // calls, passes and their alarms
    default:
      item.kind = ItemKind::Address;
      item.expr = out.pool.add(ExprNode{ExprOp::Number, Function::Sin, col(start + 1), kNoExpr, kNoExpr,
                                        static_cast<double>(v), digits});
      return true;
  }
}

// "X12.5", "X.5", "X-6.789", "X+1": the letter, a sign, the number are tokens of their own;
// LineParser::parse_letter_number_word gives the item. Returns the number's end, 0 if not plain.
size_t letter_number_word(std::string_view s, size_t start, Item& item, ParsedLine& out) {
  switch (s[start]) {
    case 'G': case 'M': case 'L': case 'P': case 'N': case 'R': return 0;  // integers with range alarms
    default: break;
  }
  size_t k = start + 1;
  double sign = 1.0;
  if (k < s.size() && (s[k] == '-' || s[k] == '+')) {
    sign = s[k] == '-' ? -1.0 : 1.0;
    ++k;
  }
  const bool number = k < s.size() && (is_digit(s[k]) || (s[k] == '.' && k + 1 < s.size() && is_digit(s[k + 1])));
  if (!number) return 0;
  const PlainDecimal d = scan_plain_decimal(s, k);
  if (exponent_follows(s, d.end) || !d.exact()) return 0;
  item.kind = ItemKind::Address;
  item.expr = out.pool.add(ExprNode{ExprOp::Number, Function::Sin, col(k), kNoExpr, kNoExpr, sign * d.value(),
                                    s.substr(k, d.end - k)});
  return d.end;
}

// The word whose letter stands at i; advances i past it. False when the word is not plain.
bool plain_word(std::string_view s, size_t& i, ParsedLine& out) {
  const size_t start = i;
  if (start + 1 < s.size() && (is_letter(s[start + 1]) || s[start + 1] == '_')) return false;  // a name
  Item item;
  item.name = s.substr(start, 1);
  item.column = col(start);
  const size_t end = digits_end(s, start + 1);
  if (end > start + 1 && (end == s.size() || s[end] != '.')) {
    if (end - start - 1 > kMaxDigits || !letter_digits_word(s, start, end, item, out)) return false;
    i = end;
  } else {
    const size_t number_end = letter_number_word(s, start, item, out);
    if (number_end == 0) return false;
    i = number_end;
  }
  out.items.push_back(item);
  return true;
}

// "N10" at the start: the block number (LineParser::parse_head). Advances i; false when the
// head is not a plain block number (N with a point or a blank, a label, a skip level).
bool block_number(std::string_view s, size_t& i, ParsedLine& out) {
  const size_t end = digits_end(s, i + 1);
  if (end == i + 1 || end - i - 1 > kMaxDigits || (end < s.size() && s[end] == '.')) return false;
  out.number = static_cast<int64_t>(digits_value(s.substr(i + 1, end - i - 1)));
  out.number_column = col(i);
  i = end;
  return true;
}

}  // namespace

bool parse_plain_word_line(std::string_view s, ParsedLine& out) {
  const uint32_t number_column = out.number_column;
  const uint32_t statement_column = out.statement_column;
  auto not_plain = [&] {
    out.number_column = number_column;
    out.statement_column = statement_column;
    return false;
  };
  out.clear();
  size_t i = skip_blanks(s, 0);
  if (i < s.size() && s[i] == 'N' && !block_number(s, i, out)) return not_plain();
  bool first = true;
  for (;;) {
    i = skip_blanks(s, i);
    if (i == s.size() || s[i] == ';') return true;
    if (!is_letter(s[i])) return not_plain();
    if (first) out.statement_column = col(i);  // parse_statement looked at the first word
    first = false;
    if (!plain_word(s, i, out)) return not_plain();
  }
}

}  // namespace drycut::parser
