// The plain-word fast path must give every line exactly what the general path (lexer + grammar)
// gives it, or leave the line to it: compared field by field on hand-picked lines and on random
// lines from the characters of CAM blocks.
#include "parser/plain_word_line.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <string>

#include "parser/ascii_case.hpp"
#include "parser/line_error.hpp"
#include "parser/line_parser.hpp"

namespace drycut::parser {
namespace {

// The outcome of parsing one line: the ParsedLine or the LineError.
struct Outcome {
  bool threw = false;
  int alarm = 0;
  uint32_t alarm_column = 0;
};

Outcome run(LineParser& p, bool general, const std::string& line, ParsedLine& out) {
  Outcome o;
  try {
    if (general) p.parse_general(line, out);
    else p.parse(line, out);
  } catch (const LineError& e) {
    o.threw = true;
    o.alarm = e.number();
    o.alarm_column = e.column();
  }
  return o;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

void expect_same(const std::string& line, const ParsedLine& a, const ParsedLine& b) {
  SCOPED_TRACE(line);
  EXPECT_EQ(a.skip_level, b.skip_level);
  EXPECT_EQ(a.number, b.number);
  EXPECT_EQ(a.number_column, b.number_column);
  EXPECT_EQ(a.label, b.label);
  EXPECT_EQ(a.statement, b.statement);
  EXPECT_EQ(a.statement_column, b.statement_column);
  ASSERT_EQ(a.items.size(), b.items.size());
  for (size_t i = 0; i < a.items.size(); ++i) {
    const Item& x = a.items[i];
    const Item& y = b.items[i];
    EXPECT_EQ(x.kind, y.kind);
    EXPECT_EQ(x.name, y.name);
    EXPECT_EQ(x.code, y.code);
    EXPECT_EQ(x.extension, y.extension);
    EXPECT_EQ(x.expr, y.expr);
    EXPECT_EQ(x.index, y.index);
    EXPECT_EQ(x.column, y.column);
    EXPECT_EQ(x.arg_count, y.arg_count);
  }
  ASSERT_EQ(a.pool.nodes.size(), b.pool.nodes.size());
  for (size_t i = 0; i < a.pool.nodes.size(); ++i) {
    const ExprNode& x = a.pool.nodes[i];
    const ExprNode& y = b.pool.nodes[i];
    EXPECT_EQ(x.op, y.op);
    EXPECT_EQ(x.func, y.func);
    EXPECT_EQ(x.column, y.column);
    EXPECT_EQ(x.a, y.a);
    EXPECT_EQ(x.b, y.b);
    EXPECT_TRUE(same_bits(x.value, y.value)) << x.value << " vs " << y.value;
    EXPECT_EQ(x.text, y.text);
  }
  EXPECT_EQ(a.pool.args.size(), b.pool.args.size());
}

// Parses `line` both ways (after the same previous line, which ParsedLine::clear partly keeps)
// and compares; returns whether the fast path took the line.
bool compare(const std::string& previous, const std::string& line) {
  LineParser fast, general;
  ParsedLine a, b;
  run(fast, false, previous, a);
  run(general, true, previous, b);
  const Outcome oa = run(fast, false, line, a);
  const Outcome ob = run(general, true, line, b);
  EXPECT_EQ(oa.threw, ob.threw) << line;
  EXPECT_EQ(oa.alarm, ob.alarm) << line;
  EXPECT_EQ(oa.alarm_column, ob.alarm_column) << line;
  if (!oa.threw && !ob.threw) expect_same(line, a, b);
  ParsedLine c;
  return parse_plain_word_line(upper_ascii(line), c);
}

TEST(PlainWordLine, TakesCamBlocksAsTheGeneralPathReadsThem) {
  const char* plain[] = {
      "G1 X12.345 Y-6.789", "X-10.910 Y-19.411 F1500", "N10 G1 X10 Y20 Z-0.5 F3000", "N10G1X10Y20",
      "x.5 y-.25 z+3", "G0 X0012 Y5. Z1.", "M30", "G64 SOFT_", "  G1   X1  ; comment", "N20",
      "G17 G90 G94 T1 D1 M6 S12000 M3", "X1.5E3", "G1 X1&Y2", "F1500", "X999999999999999",
      "g1 x1 y2 f100", "A90 B-45.5 C.125", "H1 H2 H3", "X10 X20", "N5 ; only a number"};
  for (const char* line : plain) {
    const bool taken = compare("G2 X1 Y2 I3 J4", line);
    if (std::string(line) != "G64 SOFT_") {
      EXPECT_TRUE(taken) << line;
    }
  }
}

TEST(PlainWordLine, LeavesOtherLinesToTheGeneralPath) {
  const char* other[] = {
      "N10 LABEL: G1 X1", "/1 G1 X1", "G1 X=10", "X 12", "SOFT", "CYCLE832(0.01,1)", "R1=5", "X=R1*2",
      "G1 X1 CR=5", "X1.5EX3", "G1.5 X1", "G-1", "N10.5 X1", "N 20 X1", "L100", "P3", "N10 N20", "R5",
      "X1.2.3", "X--5", "X-", "X", "X10Y", "G1 X1000000000000000", "T=\"MILL\"", "M1=3", "X1 :5",
      "\xC4" "X1", "$AA_IM[X]", "X_1", "G1 X1 + 2", "GOTOF END", "IF R1>0 GOTOF A", "X10.SPF", "N99999999999999999999 X1"};
  for (const char* line : other) EXPECT_FALSE(compare("N7 G1 X1", line)) << line;
}

TEST(PlainWordLine, RandomLinesMatchTheGeneralPath) {
  // Characters of CAM blocks and a few that end the fast path; lines of up to 24 characters.
  const std::string alphabet = "GXYZFNMLPRI 0123456789..--+ ;=(A_E";
  std::mt19937 rng(20261127);
  std::uniform_int_distribution<size_t> pick(0, alphabet.size() - 1), length(0, 24);
  std::string previous = "N1 G1 X0";
  int taken = 0;
  for (int n = 0; n < 20000; ++n) {
    std::string line;
    for (size_t k = length(rng); k > 0; --k) line += alphabet[pick(rng)];
    if (compare(previous, line)) ++taken;
    previous = line;
    if (HasFailure()) return;
  }
  EXPECT_GT(taken, 100);  // the comparison also covered lines the fast path took
}

}  // namespace
}  // namespace drycut::parser
