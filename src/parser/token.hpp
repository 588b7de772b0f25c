#pragma once
// Tokens of one NC line. Names are upper case (the language is case-insensitive); string
// literals keep their case (tool names are case-sensitive). Views point into the Lexer's
// buffers and stay valid until the next tokenize() call.
#include <cstdint>
#include <string_view>

namespace drycut::parser {

enum class TokenKind : uint8_t {
  Name,          // X, G1, CYCLE832, R1, $AA_IM, EKVI_POSTUPNE_45
  Number,        // 12.345, .5, 'H1F'
  String,        // "text" (text without the quotes)
  LParen,
  RParen,
  LBracket,
  RBracket,
  Comma,
  Assign,        // =
  Equal,         // ==
  NotEqual,      // <>
  Less,
  Greater,
  LessEqual,
  GreaterEqual,
  Plus,
  Minus,
  Star,
  Slash,
  Colon,
  Concat,        // <<
  End,           // end of line (or start of a ; comment)
};

struct Token {
  TokenKind kind = TokenKind::End;
  uint32_t column = 0;  // 1-based byte column in the decoded line
  std::string_view text;
  double number = 0.0;  // Number tokens only
};

}  // namespace drycut::parser
