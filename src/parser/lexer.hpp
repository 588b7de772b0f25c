#pragma once
// Hand-written lexer for one SINUMERIK line. Reuses its buffers: after warm-up, tokenizing a
// line allocates nothing.
#include <string>
#include <string_view>
#include <vector>

#include "parser/token.hpp"

namespace drycut::parser {

// '&' acts like a space on SINUMERIK, and so do the non-printable characters (Fundamentals,
// "Character set": "Non-printable special characters are treated like blanks").
inline bool is_lexer_blank(char c) {
  return c == ' ' || c == '&' || static_cast<unsigned char>(c) < 0x20 || c == 0x7F;
}

class Lexer {
 public:
  // Tokenizes `line` (decoded UTF-8, no line ending) into `out`, ending with an End token.
  // Throws LineError 12080 on a character that cannot start a token, an unterminated string
  // or a malformed number. `line` must outlive the tokens (strings point into it).
  void tokenize(std::string_view line, std::vector<Token>& out);
  // The two halves of tokenize: the upper-case copy of `line` that names point into (valid until
  // the next call), and the tokens of the line whose copy upper_case made last.
  std::string_view upper_case(std::string_view line);
  void tokenize_upper_cased(std::string_view line, std::vector<Token>& out);

 private:
  std::string upper_;  // upper-case copy of the line: names point into it
};

}  // namespace drycut::parser
