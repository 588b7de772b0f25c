#pragma once
// NC words are case-insensitive: the parser compares their ASCII upper-case form. Bytes outside
// a–z (UTF-8 of decoded Latin-1 comments and strings included) are left as they are.
#include <string>
#include <string_view>

namespace drycut::parser {

inline void to_upper_ascii(std::string& s) {
  for (char& c : s)
    if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
}

inline std::string upper_ascii(std::string_view s) {
  std::string out(s);
  to_upper_ascii(out);
  return out;
}

}  // namespace drycut::parser
