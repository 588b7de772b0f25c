#include "parser/lexer.hpp"

#include <gtest/gtest.h>

#include "parser/line_error.hpp"

namespace drycut::parser {
namespace {

std::vector<Token> lex(std::string_view line, Lexer& lexer) {
  std::vector<Token> t;
  lexer.tokenize(line, t);
  return t;
}

TEST(Lexer, CamBlockTokensWithColumns) {
  Lexer lx;
  const auto t = lex("N10 g1 X12.345 Y-6.789 F1500 ; comment", lx);
  ASSERT_EQ(t.size(), 9u);
  EXPECT_EQ(t[0].text, "N10");
  EXPECT_EQ(t[0].column, 1u);
  EXPECT_EQ(t[1].text, "G1");  // upper-cased
  EXPECT_EQ(t[1].column, 5u);
  EXPECT_EQ(t[2].text, "X");
  EXPECT_EQ(t[2].column, 8u);
  EXPECT_EQ(t[3].kind, TokenKind::Number);
  EXPECT_DOUBLE_EQ(t[3].number, 12.345);
  EXPECT_EQ(t[3].column, 9u);
  EXPECT_EQ(t[4].text, "Y");
  EXPECT_EQ(t[5].kind, TokenKind::Minus);
  EXPECT_EQ(t[5].column, 17u);
  EXPECT_DOUBLE_EQ(t[6].number, 6.789);
  EXPECT_EQ(t[7].text, "F1500");
  EXPECT_EQ(t[8].kind, TokenKind::End);
}

TEST(Lexer, StringsKeepTheirCase) {
  Lexer lx;
  const auto t = lex("t=\"Fr_4\"", lx);
  ASSERT_EQ(t.size(), 4u);
  EXPECT_EQ(t[0].text, "T");
  EXPECT_EQ(t[1].kind, TokenKind::Assign);
  EXPECT_EQ(t[2].kind, TokenKind::String);
  EXPECT_EQ(t[2].text, "Fr_4");
  EXPECT_EQ(t[2].column, 3u);
}

TEST(Lexer, OperatorsAndNumbers) {
  Lexer lx;
  const auto t = lex("R1==.5<>5.<=2>=3<4>1 'H1F' 'B101'", lx);
  std::vector<TokenKind> kinds;
  for (const auto& k : t) kinds.push_back(k.kind);
  const std::vector<TokenKind> want{TokenKind::Name,   TokenKind::Equal,     TokenKind::Number,       TokenKind::NotEqual,
                                    TokenKind::Number, TokenKind::LessEqual, TokenKind::Number,       TokenKind::GreaterEqual,
                                    TokenKind::Number, TokenKind::Less,      TokenKind::Number,       TokenKind::Greater,
                                    TokenKind::Number, TokenKind::Number,    TokenKind::Number,       TokenKind::End};
  EXPECT_EQ(kinds, want);
  EXPECT_DOUBLE_EQ(t[2].number, 0.5);
  EXPECT_DOUBLE_EQ(t[4].number, 5.0);
  EXPECT_DOUBLE_EQ(t[13].number, 31.0);  // 0x1F
  EXPECT_DOUBLE_EQ(t[14].number, 5.0);   // 0b101
}

TEST(Lexer, ProgramNameWithExtensionIsOneName) {
  Lexer lx;
  const auto t = lex("EKVI_POSTUPNE_45.spf P3", lx);
  ASSERT_EQ(t.size(), 3u);
  EXPECT_EQ(t[0].text, "EKVI_POSTUPNE_45.SPF");
  EXPECT_EQ(t[1].text, "P3");
}

TEST(Lexer, AmpersandIsASpaceAndCommentEndsTheLine) {
  Lexer lx;
  const auto t = lex("G1&X1 ; \"unterminated in a comment is fine", lx);
  ASSERT_EQ(t.size(), 3u);
  EXPECT_EQ(t[1].text, "X1");
}

TEST(Lexer, ErrorsCarryTheColumn) {
  Lexer lx;
  std::vector<Token> t;
  try {
    lx.tokenize("G1 X1 # Y", t);
    FAIL();
  } catch (const LineError& e) {
    EXPECT_EQ(e.number(), 12080);
    EXPECT_EQ(e.column(), 7u);
  }
  try {
    lx.tokenize("MSG(\"abc)", t);
    FAIL();
  } catch (const LineError& e) {
    EXPECT_EQ(e.column(), 5u);
  }
  // Non-printable characters are blanks (Fundamentals, "Character set"): "X1\0Y2" is X1 Y2.
  lx.tokenize(std::string_view("X1\0Y2\x12", 6), t);
  ASSERT_EQ(t.size(), 3u);  // X1, Y2, end
  EXPECT_EQ(t[1].text, "Y2");
}

// PGA Fundamentals, "Identifiers": names begin with two letters (or an underscore), so one
// letter followed by a digit is an address word that ends with its digits.
TEST(Lexer, CompactAddressWordsSplitAtTheNextLetter) {
  Lexer lx;
  std::vector<Token> t;
  lx.tokenize("N10G1X10Y-2.5", t);
  ASSERT_EQ(t.size(), 7u);
  EXPECT_EQ(t[0].text, "N10");
  EXPECT_EQ(t[1].text, "G1");
  EXPECT_EQ(t[2].text, "X10");
  EXPECT_EQ(t[3].text, "Y");
  EXPECT_EQ(t[4].kind, TokenKind::Minus);
  EXPECT_DOUBLE_EQ(t[5].number, 2.5);
  lx.tokenize("s12m3", t);
  ASSERT_EQ(t.size(), 3u);
  EXPECT_EQ(t[0].text, "S12");
  EXPECT_EQ(t[1].text, "M3");
  lx.tokenize("X.5Y2", t);  // a name may follow a number directly
  ASSERT_EQ(t.size(), 4u);
  EXPECT_EQ(t[0].text, "X");
  EXPECT_DOUBLE_EQ(t[1].number, 0.5);
  EXPECT_EQ(t[2].text, "Y2");
  lx.tokenize("X1=10 EKVI_45 CYCLE81", t);  // X1= is an extended address; names stay whole
  EXPECT_EQ(t[0].text, "X1");
  EXPECT_EQ(t[1].kind, TokenKind::Assign);
  EXPECT_EQ(t[3].text, "EKVI_45");
  EXPECT_EQ(t[4].text, "CYCLE81");
}

}  // namespace
}  // namespace drycut::parser

namespace drycut::parser {
namespace {

// PGA Fundamentals, "Arithmetic parameters": EX writes a power of ten (1.874EX8, -0.1EX-5).
TEST(LexerConformance, ExponentNotationIsOneNumber) {
  Lexer lx;
  std::vector<Token> t;
  lx.tokenize("R1=1.5EX3 R2=-0.1EX-5 R3=2EX+2", t);
  ASSERT_EQ(t.size(), 11u);
  EXPECT_DOUBLE_EQ(t[2].number, 1500.0);
  EXPECT_EQ(t[3].text, "R2");
  EXPECT_DOUBLE_EQ(t[6].number, 0.1e-5);
  EXPECT_DOUBLE_EQ(t[9].number, 200.0);
}

// EX followed by no digit is not an exponent: "2EXP" stays a number and a name.
TEST(LexerConformance, ExWithoutDigitsIsAName) {
  Lexer lx;
  std::vector<Token> t;
  lx.tokenize("X2 EXTCALL", t);
  ASSERT_EQ(t.size(), 3u);
  EXPECT_EQ(t[1].text, "EXTCALL");
}

// The address rule: one letter and digits is one word, so compact blocks split per word.
TEST(LexerConformance, CompactBlockSplitsIntoWords) {
  Lexer lx;
  std::vector<Token> t;
  lx.tokenize("N10G0X.5Y2S12M3", t);
  ASSERT_EQ(t.size(), 8u);
  EXPECT_EQ(t[0].text, "N10");
  EXPECT_EQ(t[1].text, "G0");
  EXPECT_EQ(t[2].text, "X");
  EXPECT_DOUBLE_EQ(t[3].number, 0.5);
  EXPECT_EQ(t[4].text, "Y2");
  EXPECT_EQ(t[5].text, "S12");
  EXPECT_EQ(t[6].text, "M3");
}

}  // namespace
}  // namespace drycut::parser
