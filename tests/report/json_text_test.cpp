// The hand-written JSON numbers and strings of the streaming run report: rounded to the given
// decimals without trailing zeros, no "-0", null for what JSON cannot hold, strings escaped and
// invalid UTF-8 replaced. Expected texts written by hand.
#include <gtest/gtest.h>

#include <limits>

#include "report/json_text.hpp"

namespace drycut::report {
namespace {

std::string number(double v, int decimals) {
  std::string s;
  append_json_number(s, v, decimals);
  return s;
}

std::string string(std::string_view v) {
  std::string s;
  append_json_string(s, v);
  return s;
}

TEST(JsonText, NumbersAreRoundedWithoutTrailingZeros) {
  EXPECT_EQ(number(1500.0, 3), "1500");
  EXPECT_EQ(number(1461.7664, 3), "1461.766");
  EXPECT_EQ(number(0.00866681026, 7), "0.0086668");
  EXPECT_EQ(number(0.25, 6), "0.25");
  EXPECT_EQ(number(-2.5, 1), "-2.5");
  EXPECT_EQ(number(-0.00000001, 6), "0");
  EXPECT_EQ(number(-0.0, 3), "0");
  EXPECT_EQ(number(0.0, 0), "0");
  EXPECT_EQ(number(123.0, 0), "123");
  EXPECT_EQ(number(std::numeric_limits<double>::quiet_NaN(), 3), "null");
  EXPECT_EQ(number(std::numeric_limits<double>::infinity(), 3), "null");
  EXPECT_EQ(number(1e300, 2).size(), 301u);  // fixed notation, still a JSON number
  EXPECT_EQ(number(2e18, 3), "2000000000000000000");  // beyond the scaled-integer path
  EXPECT_EQ(number(0.05, 7), "0.05");
  EXPECT_EQ(number(1.0000001, 7), "1.0000001");
  EXPECT_EQ(number(-12.5, 0), "-13");  // half away from zero
  EXPECT_EQ(number(0.1234567, 20), "0.12345670000000000255");  // more decimals than the fast path
  std::string i;
  append_json_integer(i, 18446744073709551615ull);
  EXPECT_EQ(i, "18446744073709551615");
}

TEST(JsonText, StringsAreEscaped) {
  EXPECT_EQ(string("G1"), "\"G1\"");
  EXPECT_EQ(string("a\"b\\c"), "\"a\\\"b\\\\c\"");
  EXPECT_EQ(string("tab\there\n"), "\"tab\\u0009here\\u000a\"");
  EXPECT_EQ(string("M6 \xC3\xA9"), "\"M6 \xC3\xA9\"");           // valid UTF-8 (é) kept
  EXPECT_EQ(string("x\xFFy"), "\"x\xEF\xBF\xBDy\"");              // invalid byte replaced
  EXPECT_EQ(string("\xE2\x82"), "\"\xEF\xBF\xBD\xEF\xBF\xBD\"");  // truncated sequence
}

}  // namespace
}  // namespace drycut::report
