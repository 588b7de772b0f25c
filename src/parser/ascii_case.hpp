#pragma once
// NC words are case-insensitive: the parser compares their ASCII upper-case form. Bytes outside
// a–z (UTF-8 of decoded Latin-1 comments and strings included) are left as they are.
#include <string>
#include <string_view>

namespace drycut::parser {

inline void to_upper_ascii(std::string& s) {
  // Branch-free so that the compiler vectorises it: every line of a program passes here.
  for (char& c : s) {
    const auto u = static_cast<unsigned char>(c - 'a');
    c = static_cast<char>(c - (u < 26 ? 32 : 0));
  }
}

inline std::string upper_ascii(std::string_view s) {
  std::string out(s);
  to_upper_ascii(out);
  return out;
}

}  // namespace drycut::parser
