#pragma once
// Hand-written lexer for one SINUMERIK line. Reuses its buffers: after warm-up, tokenizing a
// line allocates nothing.
#include <string>
#include <string_view>
#include <vector>

#include "parser/token.hpp"

namespace drycut::parser {

class Lexer {
 public:
  // Tokenizes `line` (decoded UTF-8, no line ending) into `out`, ending with an End token.
  // Throws LineError 12080 on a character that cannot start a token, an unterminated string
  // or a malformed number. `line` must outlive the tokens (strings point into it).
  void tokenize(std::string_view line, std::vector<Token>& out);

 private:
  std::string upper_;  // upper-case copy of the line: names point into it
};

}  // namespace drycut::parser
