#pragma once
// A plain decimal number as NC programs write coordinates: digits with at most one point
// ("12.345", "5.", ".5"), read in one pass. Shared by the lexer and the plain-word line parser so
// that both give a coordinate the same double.
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace drycut::parser {

// Digits with at most one point, read from s[i] on: their integer, how many digits, how many
// after the point (-1: no point). With at most 15 significant digits the integer and the power of
// ten are exact doubles, so one division gives the correctly rounded value from_chars would.
struct PlainDecimal {
  uint64_t mantissa = 0;
  int count = 0;
  int decimals = -1;
  size_t end = 0;  // where the digits stop
  bool exact() const { return count > 0 && count <= 15; }
  // Only when exact(): the integer is below 10^15, so it converts as a signed one (one
  // instruction; an unsigned 64-bit conversion takes a branch and several on x86-64).
  double value() const {
    static constexpr double kPow10[] = {1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};
    return static_cast<double>(static_cast<int64_t>(mantissa)) / kPow10[decimals > 0 ? decimals : 0];
  }
};

inline PlainDecimal scan_plain_decimal(std::string_view s, size_t i) {
  PlainDecimal d;
  for (; i < s.size(); ++i) {
    const char c = s[i];
    if (c >= '0' && c <= '9') {
      d.mantissa = d.mantissa * 10 + static_cast<uint64_t>(c - '0');  // wraps past 19 digits: not exact()
      ++d.count;
      if (d.decimals >= 0) ++d.decimals;
    } else if (c == '.' && d.decimals < 0) {
      d.decimals = 0;
    } else {
      break;
    }
  }
  d.end = i;
  return d;
}

// "EX" right after a number: the number has a power of ten (R1=1.874EX8) and is not plain.
inline bool exponent_follows(std::string_view s, size_t end) {
  return end + 1 < s.size() && s[end] == 'E' && s[end + 1] == 'X';
}

}  // namespace drycut::parser
