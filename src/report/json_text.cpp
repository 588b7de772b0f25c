#include "report/json_text.hpp"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <system_error>

namespace drycut::report {

namespace {

constexpr uint64_t kPow10[] = {1,          10,          100,          1000,          10000,
                               100000,     1000000,     10000000,     100000000,     1000000000,
                               10000000000, 100000000000, 1000000000000};

// The general case: std::to_chars in fixed notation, trailing zeros dropped.
void append_fixed(std::string& out, double value, int decimals) {
  char buf[400];  // fixed notation of the largest double: 309 digits and the decimals
  const auto r = std::to_chars(buf, buf + sizeof buf, value, std::chars_format::fixed, decimals);
  if (r.ec != std::errc()) {
    out += "null";
    return;
  }
  char* end = r.ptr;
  if (decimals > 0) {
    while (end[-1] == '0') --end;
    if (end[-1] == '.') --end;
  }
  if (end - buf == 2 && buf[0] == '-' && buf[1] == '0') {
    out += '0';  // -0.0000001 rounded: no "-0"
    return;
  }
  out.append(buf, end);
}

}  // namespace

void append_json_number(std::string& out, double value, int decimals) {
  if (!std::isfinite(value)) {
    out += "null";
    return;
  }
  // The common case (a row value below ~1e11 with at most 12 decimals) as a scaled integer:
  // about three times faster than to_chars in fixed notation. Rounding is half away from zero
  // of the double's value times 10^decimals, so a tie may round up where to_chars rounds the
  // exact binary value down: one unit in the last written decimal at most.
  if (decimals >= 0 && decimals <= 12) {
    const double scaled = std::round(std::abs(value) * static_cast<double>(kPow10[decimals]));
    if (scaled < 1e18) {
      const uint64_t n = static_cast<uint64_t>(scaled), unit = kPow10[decimals];
      if (value < 0 && n != 0) out += '-';
      append_json_integer(out, n / unit);
      uint64_t fraction = n % unit;
      if (fraction == 0) return;
      int digits = decimals;
      while (fraction % 10 == 0) {  // drop trailing zeros
        fraction /= 10;
        --digits;
      }
      char buf[16];
      for (int i = digits - 1; i >= 0; --i, fraction /= 10) buf[i] = static_cast<char>('0' + fraction % 10);
      out += '.';
      out.append(buf, static_cast<size_t>(digits));
      return;
    }
  }
  append_fixed(out, value, decimals);
}

void append_json_integer(std::string& out, unsigned long long value) {
  char buf[24];
  const auto r = std::to_chars(buf, buf + sizeof buf, value);
  out.append(buf, r.ptr);
}

namespace {

// Length of the valid UTF-8 sequence starting at s[i], or 0 when it is not one.
size_t utf8_sequence_length(std::string_view s, size_t i) {
  const auto byte = [&](size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char c = byte(i);
  size_t n = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xE ? 3 : (c >> 3) == 0x1E ? 4 : 0;
  if (n == 0 || i + n > s.size()) return 0;
  for (size_t k = 1; k < n; ++k)
    if ((byte(i + k) & 0xC0) != 0x80) return 0;
  if (n == 2 && c < 0xC2) return 0;  // overlong
  return n;
}

}  // namespace

void append_json_string(std::string& out, std::string_view text) {
  static constexpr char kHex[] = "0123456789abcdef";
  out += '"';
  for (size_t i = 0; i < text.size();) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += static_cast<char>(c);
    } else if (c < 0x20) {
      out += "\\u00";
      out += kHex[c >> 4];
      out += kHex[c & 0xF];
    } else if (c >= 0x80) {
      const size_t n = utf8_sequence_length(text, i);
      if (n == 0) {
        out += "\xEF\xBF\xBD";  // U+FFFD
        ++i;
      } else {
        out.append(text.substr(i, n));
        i += n;
      }
      continue;
    } else {
      out += static_cast<char>(c);
    }
    ++i;
  }
  out += '"';
}

}  // namespace drycut::report
