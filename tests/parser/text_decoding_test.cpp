#include "parser/text_decoding.hpp"

#include <gtest/gtest.h>

namespace drycut::parser {
namespace {

TEST(TextDecoding, AsciiAndUtf8PassUnchanged) {
  std::string out;
  decode_line_to_utf8("G1 X1", out);
  EXPECT_EQ(out, "G1 X1");
  decode_line_to_utf8("; Fr\xC3\xA4se", out);  // UTF-8 "Fräse"
  EXPECT_EQ(out, "; Fr\xC3\xA4se");
  EXPECT_TRUE(is_ascii("G1 X1 Y2 Z3 F100"));
  EXPECT_FALSE(is_ascii("G1 X1 Y2 Z3 F100 \xE4"));
}

TEST(TextDecoding, Latin1AndCp1252BecomeUtf8) {
  std::string out;
  decode_line_to_utf8("; Fr\xE4se \xDF", out);  // Latin-1 ä, ß
  EXPECT_EQ(out, "; Fr\xC3\xA4se \xC3\x9F");
  decode_line_to_utf8("; 5\x80", out);  // CP1252 euro sign -> U+20AC
  EXPECT_EQ(out, "; 5\xE2\x82\xAC");
}

}  // namespace
}  // namespace drycut::parser
