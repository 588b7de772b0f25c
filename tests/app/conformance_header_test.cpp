// The conformance header reader (conformance_header.hpp): what it takes from a well-formed header,
// and that every malformed or incomplete header is refused with a reason instead of being
// half-read (an ignored expectation would let a conformance program pass without checking it).
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "conformance_header.hpp"

namespace {

using drycut::testing::ConformanceSpec;
using drycut::testing::read_conformance_header;

bool read(const std::string& text, ConformanceSpec& spec, std::string& error) {
  std::istringstream in(text);
  return read_conformance_header(in, spec, error);
}

constexpr const char* kRule = "; rule: G2 runs clockwise (source: Fundamentals, circular interpolation)\n";

TEST(ConformanceHeader, ReadsEveryDirective) {
  ConformanceSpec s;
  std::string error;
  ASSERT_TRUE(read(std::string("%_N_ARC_MPF\n") + kRule +
                       ";   continued on the next comment line\n"
                       "; expect: alarm 14040 line 9\n"
                       "; expect-warning: 990002\n"
                       "; expect-warning: 10763\n"
                       "; hand computation: centre (0,0), radius 10 -> end (10, 0)\n"
                       "; expect-end: X10 Y-0.5 z2.5e1\n"
                       "; expect-time: 12.5 tol 0.01\n"
                       "; expect-listing: ARC.elements\n"
                       "; expect-tool-centre: ARC_TC.elements\n"
                       "\n"
                       "G0 X0 Y0 ; expect nothing here, a plain comment\n"
                       "M30\n",
                   s, error))
      << error;
  EXPECT_NE(s.rule.find("(source: Fundamentals"), std::string::npos);
  EXPECT_NE(s.rule.find("continued on the next comment line"), std::string::npos);
  EXPECT_EQ(s.rule.find("hand computation"), std::string::npos);
  EXPECT_TRUE(s.expect_alarm);
  EXPECT_EQ(s.alarm_number, 14040);
  EXPECT_EQ(s.alarm_line, 9);
  EXPECT_EQ(s.warnings, (std::vector<int>{990002, 10763}));
  ASSERT_TRUE(s.has_end);
  EXPECT_DOUBLE_EQ(*s.end_mm[0], 10.0);
  EXPECT_DOUBLE_EQ(*s.end_mm[1], -0.5);
  EXPECT_DOUBLE_EQ(*s.end_mm[2], 25.0);
  ASSERT_TRUE(s.time_s.has_value());
  EXPECT_DOUBLE_EQ(*s.time_s, 12.5);
  EXPECT_DOUBLE_EQ(s.time_tolerance_s, 0.01);
  EXPECT_EQ(s.listing, "ARC.elements");
  EXPECT_EQ(s.tool_centre_listing, "ARC_TC.elements");
}

TEST(ConformanceHeader, OkWithOnlyTheRequiredLines) {
  ConformanceSpec s;
  std::string error;
  ASSERT_TRUE(read(std::string(kRule) + "; expect: ok\nG1 X1 F100\n", s, error)) << error;
  EXPECT_FALSE(s.expect_alarm);
  EXPECT_TRUE(s.warnings.empty());
  EXPECT_FALSE(s.has_end);
  EXPECT_FALSE(s.time_s.has_value());
  EXPECT_TRUE(s.listing.empty());
}

struct Malformed {
  const char* what;
  std::string text;
  const char* reason;  // a word the error must contain
};

TEST(ConformanceHeader, RefusesMalformedHeaders) {
  const std::string rule = kRule;
  const Malformed cases[] = {
      {"no header at all", "G1 X1 F100\nM30\n", "rule"},
      {"no rule", "; expect: ok\nM30\n", "rule"},
      {"no expect", rule + "M30\n", "expect"},
      {"rule without source", "; rule: G2 runs clockwise\n; expect: ok\n", "source"},
      {"empty rule", "; rule:\n; expect: ok\n", "empty"},
      {"expect neither ok nor alarm", rule + "; expect: fine\n", "expect"},
      {"alarm without line", rule + "; expect: alarm 14040\n", "expect"},
      {"alarm with a non-number", rule + "; expect: alarm 14O40 line 3\n", "expect"},
      {"alarm line zero", rule + "; expect: alarm 14040 line 0\n", "expect"},
      {"expect twice", rule + "; expect: ok\n; expect: alarm 1 line 2\n", "twice"},
      {"rule twice", rule + rule + "; expect: ok\n", "twice"},
      {"warning not a number", rule + "; expect: ok\n; expect-warning: not-modelled\n", "warning"},
      {"two warnings on one line", rule + "; expect: ok\n; expect-warning: 1 2\n", "warning"},
      {"end with an unknown axis", rule + "; expect: ok\n; expect-end: X1 A2\n", "expect-end"},
      {"end with an axis twice", rule + "; expect: ok\n; expect-end: X1 X2\n", "expect-end"},
      {"end with a bad number", rule + "; expect: ok\n; expect-end: X1.2.3\n", "expect-end"},
      {"end empty", rule + "; expect: ok\n; expect-end:\n", "expect-end"},
      {"time without tol", rule + "; expect: ok\n; expect-time: 12.5\n", "expect-time"},
      {"time with zero tolerance", rule + "; expect: ok\n; expect-time: 12.5 tol 0\n", "expect-time"},
      {"time with a word", rule + "; expect: ok\n; expect-time: 12.5 s tol 0.1\n", "expect-time"},
      {"listing in another folder", rule + "; expect: ok\n; expect-listing: ../x.elements\n", "expect-listing"},
      {"listing empty", rule + "; expect: ok\n; expect-listing:\n", "expect-listing"},
      {"tool-centre listing in another folder", rule + "; expect: ok\n; expect-tool-centre: a/x.elements\n",
       "expect-tool-centre"},
      {"misspelt directive", rule + "; expect: ok\n; expect-warnings: 990002\n", "unknown"},
      {"misspelt expect", rule + "; expects: ok\n", "unknown"},
      {"capitalised key", rule + "; Expect: ok\n", "lower case"},
      {"directive below the program", rule + "; expect: ok\nG1 X1 F100\n; expect-warning: 990002\n", "header"},
  };
  for (const auto& c : cases) {
    ConformanceSpec s;
    std::string error;
    EXPECT_FALSE(read(c.text, s, error)) << c.what;
    EXPECT_NE(error.find(c.reason), std::string::npos) << c.what << ": " << error;
  }
}

TEST(ConformanceHeader, ErrorsNameTheLine) {
  ConformanceSpec s;
  std::string error;
  EXPECT_FALSE(read(std::string(kRule) + "; expect: ok\n; expect-time: soon\n", s, error));
  EXPECT_EQ(error.rfind("line 3:", 0), 0u) << error;
}

}  // namespace
