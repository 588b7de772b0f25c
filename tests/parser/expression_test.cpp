// Expression values are checked against hand-computed numbers.
#include "parser/expression_api.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "machine/alarm.hpp"

namespace drycut::parser {
namespace {

double ev(std::string_view s, const std::map<std::string, double>& v = {}) { return evaluate_expression(s, v); }

int alarm_of(std::string_view s, const std::map<std::string, double>& v = {}) {
  try {
    ev(s, v);
  } catch (const AlarmError& e) {
    return e.alarm().number;
  }
  return 0;
}

TEST(Expression, ArithmeticPrecedence) {
  EXPECT_DOUBLE_EQ(ev("1+2*3"), 7.0);
  EXPECT_DOUBLE_EQ(ev("(1+2)*3"), 9.0);
  EXPECT_DOUBLE_EQ(ev("10-4-3"), 3.0);  // left associative
  EXPECT_DOUBLE_EQ(ev("2*3/4"), 1.5);
  EXPECT_DOUBLE_EQ(ev("-2*3"), -6.0);
  EXPECT_DOUBLE_EQ(ev("7 DIV 2"), 3.0);
  EXPECT_DOUBLE_EQ(ev("-7 DIV 2"), -3.0);  // truncates towards zero
  EXPECT_DOUBLE_EQ(ev("7 MOD 3"), 1.0);
  EXPECT_DOUBLE_EQ(ev("1+7 MOD 3*2"), 3.0);  // MOD binds like *: 1 + ((7 MOD 3) * 2)
}

TEST(Expression, TrigonometryInDegrees) {
  EXPECT_NEAR(ev("SIN(30)"), 0.5, 1e-15);
  EXPECT_NEAR(ev("COS(60)"), 0.5, 1e-15);
  EXPECT_NEAR(ev("TAN(45)"), 1.0, 1e-15);
  EXPECT_NEAR(ev("ASIN(0.5)"), 30.0, 1e-12);
  EXPECT_NEAR(ev("ACOS(0)"), 90.0, 1e-12);
  EXPECT_NEAR(ev("ATAN2(1,-1)"), 135.0, 1e-12);
  EXPECT_NEAR(ev("ATAN2(-1,0)"), -90.0, 1e-12);
}

TEST(Expression, Functions) {
  EXPECT_DOUBLE_EQ(ev("SQRT(16)"), 4.0);
  EXPECT_DOUBLE_EQ(ev("ABS(-2.5)"), 2.5);
  EXPECT_DOUBLE_EQ(ev("POT(3)"), 9.0);  // POT = square
  EXPECT_DOUBLE_EQ(ev("POT(2,10)"), 1024.0);
  EXPECT_DOUBLE_EQ(ev("TRUNC(-2.7)"), -2.0);
  EXPECT_DOUBLE_EQ(ev("ROUND(2.5)"), 3.0);
  EXPECT_DOUBLE_EQ(ev("ROUND(-2.5)"), -3.0);
  EXPECT_NEAR(ev("LN(EXP(2))"), 2.0, 1e-15);
  EXPECT_DOUBLE_EQ(ev("MINVAL(3,-1)+MAXVAL(3,-1)"), 2.0);
}

TEST(Expression, ComparisonsAndLogicBindAsOnTheControl) {
  EXPECT_DOUBLE_EQ(ev("2>1"), 1.0);
  EXPECT_DOUBLE_EQ(ev("2<>2"), 0.0);
  EXPECT_DOUBLE_EQ(ev("(2>1) AND (3<=3)"), 1.0);
  EXPECT_DOUBLE_EQ(ev("(2>1) AND (3<3)"), 0.0);
  EXPECT_DOUBLE_EQ(ev("0 OR 1 AND 0"), 0.0);  // AND before OR: 0 OR (1 AND 0)
  EXPECT_DOUBLE_EQ(ev("1 XOR 1"), 0.0);
  EXPECT_DOUBLE_EQ(ev("NOT 0"), 1.0);
  // Comparisons bind least: 1+1 == 2 is (1+1) == 2; 3 > 2 AND 0 is 3 > (2 AND 0) = 3 > 0.
  EXPECT_DOUBLE_EQ(ev("1+1==2"), 1.0);
  EXPECT_DOUBLE_EQ(ev("3>2 AND 0"), 1.0);
  EXPECT_DOUBLE_EQ(ev("TRUE AND NOT FALSE"), 1.0);
}

TEST(Expression, VariablesCaseInsensitive) {
  // The thesis contour r(theta) at theta = 0 and 45 degrees: 18 + 4 cos(6t) cos(2t).
  EXPECT_NEAR(ev("18+4*COS(6*T)*COS(2*T)", {{"t", 0.0}}), 22.0, 1e-12);
  EXPECT_NEAR(ev("18+4*COS(6*T)*COS(2*T)", {{"T", 45.0}}), 18.0, 1e-12);
  EXPECT_NEAR(ev("18+4*cos(6*t)*cos(2*t)", {{"T", 90.0}}), 22.0, 1e-12);
}

TEST(Expression, Alarms) {
  EXPECT_EQ(alarm_of("1/0"), 14051);
  EXPECT_EQ(alarm_of("1 MOD 0"), 14051);
  EXPECT_EQ(alarm_of("SQRT(-1)"), 14051);
  EXPECT_EQ(alarm_of("ASIN(1.5)"), 14051);
  EXPECT_EQ(alarm_of("LN(0)"), 14051);
  EXPECT_EQ(alarm_of("TAN(90)"), 14051);
  EXPECT_EQ(alarm_of("EXP(1000)"), 14051);
  EXPECT_EQ(alarm_of("Q+1"), 12550);
  EXPECT_EQ(alarm_of("FOO(1)"), 12550);
  EXPECT_EQ(alarm_of("(1+2"), 12080);
  EXPECT_EQ(alarm_of("1+2)"), 12080);
  EXPECT_EQ(alarm_of("1+"), 12080);
  EXPECT_EQ(alarm_of("SIN(1,2)"), 12080);
  EXPECT_EQ(alarm_of(std::string(1000, '(') + "1" + std::string(1000, ')')), 12080);
  EXPECT_EQ(alarm_of("\"text\"+1"), 12150);
}

// A flat chain is as deep as it is long for the recursive evaluator: 18,000 comparisons or
// 20,000 `<<` overflowed the stack (a crash). Past 500 they are an alarm; a chain within it
// computes (1==1 is 1, so the whole chain is 1).
TEST(Expression, OverlongComparisonChainIsAnAlarmNotACrash) {
  std::string chain = "1", concat = "\"A\"", fine = "1";
  for (int i = 0; i < 18000; ++i) chain += "==1";
  for (int i = 0; i < 20000; ++i) concat += "<<\"A\"";
  for (int i = 0; i < 500; ++i) fine += "==1";
  EXPECT_EQ(alarm_of(chain), 12080);
  EXPECT_EQ(alarm_of(concat), 12080);
  EXPECT_DOUBLE_EQ(ev(fine), 1.0);
}

TEST(Expression, AlarmKnowsTheColumn) {
  try {
    ev("1+2/(3-3)");
    FAIL();
  } catch (const AlarmError& e) {
    EXPECT_EQ(e.alarm().where.column, 4u);  // the '/'
    EXPECT_EQ(e.alarm().where.line, 1u);
  }
}

}  // namespace
}  // namespace drycut::parser

namespace drycut::parser {
namespace {

// Job Planning, "String operations": results checked through numbers and comparisons.
TEST(ExpressionLanguage, StringFunctionsAndConcatenation) {
  EXPECT_DOUBLE_EQ(evaluate_expression("STRLEN(\"AB\"<<\"CDE\")", {}), 5.0);
  EXPECT_DOUBLE_EQ(evaluate_expression("SUBSTR(\"ACKNOWLEDGE\",3,4)==\"NOWL\"", {}), 1.0);
  EXPECT_DOUBLE_EQ(evaluate_expression("INDEX(\"ABCABC\",\"C\")+RINDEX(\"ABCABC\",\"C\")*10", {}), 52.0);
  EXPECT_DOUBLE_EQ(evaluate_expression("MINDEX(\"ABCDEF\",\"FD\")", {}), 3.0);
  EXPECT_DOUBLE_EQ(evaluate_expression("\"X\"<<1+2==\"X3\"", {}), 1.0);  // + before <<, << before ==
  EXPECT_DOUBLE_EQ(evaluate_expression("TOUPPER(\"ab1\")==\"AB1\"", {}), 1.0);
  EXPECT_DOUBLE_EQ(evaluate_expression("1.5EX2", {}), 150.0);
}

// Job Planning, "Priority of the operations": bit operators between arithmetic and logic.
TEST(ExpressionLanguage, BitOperatorPriorities) {
  EXPECT_DOUBLE_EQ(evaluate_expression("1 B_OR 1 B_XOR 1", {}), 1.0);
  EXPECT_DOUBLE_EQ(evaluate_expression("6 B_AND 3+1", {}), 4.0);
  EXPECT_DOUBLE_EQ(evaluate_expression("1 AND 2 B_AND 2", {}), 1.0);
  EXPECT_DOUBLE_EQ(evaluate_expression("0==0 AND 0", {}), 1.0);
}

}  // namespace
}  // namespace drycut::parser
