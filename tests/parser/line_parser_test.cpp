#include "parser/line_parser.hpp"

#include <gtest/gtest.h>

#include "parser/line_error.hpp"

namespace drycut::parser {
namespace {

struct Parsed {
  LineParser parser;
  ParsedLine line;
  std::string text;
  const ParsedLine& operator()(std::string s) {
    text = std::move(s);
    parser.parse(text, line);
    return line;
  }
};

TEST(LineParser, BlockNumberSkipLabelAndWords) {
  Parsed p;
  const auto& l = p("/3 N20 MARK1: G1 X12.5 Y-3 M3 S1000");
  EXPECT_EQ(l.skip_level, 3);
  ASSERT_TRUE(l.number);
  EXPECT_EQ(*l.number, 20);
  EXPECT_EQ(l.label, "MARK1");
  ASSERT_EQ(l.items.size(), 5u);
  EXPECT_EQ(l.items[0].kind, ItemKind::G);
  EXPECT_EQ(l.items[0].code, 1);
  EXPECT_EQ(l.items[1].kind, ItemKind::Address);
  EXPECT_EQ(l.items[1].name, "X");
  EXPECT_DOUBLE_EQ(l.pool[l.items[1].expr].value, 12.5);
  EXPECT_DOUBLE_EQ(l.pool[l.items[2].expr].value, -3.0);
  EXPECT_EQ(l.items[3].kind, ItemKind::M);
  EXPECT_EQ(l.items[4].name, "S");
  EXPECT_DOUBLE_EQ(l.pool[l.items[4].expr].value, 1000.0);
}

TEST(LineParser, SynchronizedActionNamesWhatItWrites) {
  // The condition's reads and comparisons are no targets; a computed index names the whole
  // variable; targets after ELSE count too; the next line starts empty.
  Parsed p;
  const auto& l = p("ID=1 WHEN $AA_IM[X]>=50 DO $R20=1 $A_OUT[5]=1 GUD_NOCKE=$AA_IM[X] $R[$AC_MARKER[1]]=2 "
                    "ARR[2,3]=1 ELSE $AC_MARKER[1]=$AC_MARKER[1]+1");
  EXPECT_EQ(l.statement, Statement::SyncAction);
  const std::vector<std::string> expected{"$R20", "$A_OUT[5]", "GUD_NOCKE", "$R", "ARR[2,3]", "$AC_MARKER[1]"};
  EXPECT_EQ(l.sync_targets, expected);
  EXPECT_TRUE(p("G1 X10").sync_targets.empty());
  EXPECT_TRUE(p("WHENEVER $AA_IM[X]==$R1 DO M99").sync_targets.empty());
  EXPECT_TRUE(p("IDS=2 DO $AC_MARKER[1]=0").sync_targets.size() == 1);  // no condition: every cycle
  for (const char* bad : {"ID=1 WHENEVER $AA_IM[X]>10 M8", "ID=2 WHEN DO M8", "ID=3 WHEN $AA_IM[X]>5 DO"}) {
    try {
      p(bad);
      ADD_FAILURE() << bad << " was accepted";
    } catch (const LineError& e) {
      EXPECT_EQ(e.number(), 12080) << bad;
    }
  }
}

TEST(LineParser, MainBlockNumberAndPlainSkip) {
  Parsed p;
  const auto& l = p("/ :100 G0 Z5");
  EXPECT_EQ(l.skip_level, 0);
  EXPECT_EQ(*l.number, 100);
}

TEST(LineParser, ExtendedAddressesAndAssignments) {
  Parsed p;
  const auto& l = p("G2 X10 I1=5 CR=-3 AP=45 RP=10 TURN=2 PW=3 X=AC(5) Y=IC(-1) R1=R2*2 R[3]=1");
  ASSERT_EQ(l.items.size(), 12u);
  EXPECT_EQ(l.items[2].kind, ItemKind::Assign);
  EXPECT_EQ(l.items[2].name, "I1");
  EXPECT_EQ(l.items[3].name, "CR");
  EXPECT_EQ(l.items[8].name, "X");
  EXPECT_EQ(l.pool[l.items[8].expr].op, ExprOp::Call);
  EXPECT_EQ(l.pool[l.items[8].expr].func, Function::AbsoluteMode);
  EXPECT_EQ(l.pool[l.items[9].expr].func, Function::IncrementalMode);
  EXPECT_EQ(l.items[10].name, "R1");
  EXPECT_NE(l.items[11].index, kNoExpr);
}

TEST(LineParser, ToolNameCommandsAndProcedures) {
  Parsed p;
  const auto& l = p("T=\"Fr_4\" D1 ASPLINE BTAN CYCLE832(0.01,1) MSG(\"Hi there\") SPLINEPATH(1,X,Y,Z) G642");
  ASSERT_EQ(l.items.size(), 8u);
  EXPECT_EQ(l.items[0].kind, ItemKind::ToolName);
  EXPECT_EQ(l.items[0].name, "Fr_4");
  EXPECT_EQ(l.items[1].kind, ItemKind::Address);
  EXPECT_EQ(l.items[2].kind, ItemKind::Name);
  EXPECT_EQ(l.items[2].name, "ASPLINE");
  EXPECT_EQ(l.items[4].kind, ItemKind::Procedure);
  EXPECT_EQ(l.items[4].arg_count, 2u);
  EXPECT_EQ(l.items[5].arg_count, 1u);
  EXPECT_EQ(l.pool[l.pool.args[l.items[5].arg_first]].text, "Hi there");
  EXPECT_EQ(l.items[6].arg_count, 4u);
  EXPECT_EQ(l.items[7].kind, ItemKind::G);
  EXPECT_EQ(l.items[7].code, 642);
}

TEST(LineParser, CallsAndPasses) {
  Parsed p;
  auto l = &p("L123 P3");
  EXPECT_EQ(l->items[0].kind, ItemKind::LCall);
  EXPECT_EQ(l->items[0].name, "L123");
  EXPECT_EQ(l->items[1].kind, ItemKind::Passes);
  EXPECT_EQ(l->items[1].code, 3);
  l = &p("CALL \"Sub1\" P2");
  EXPECT_EQ(l->statement, Statement::Call);
  EXPECT_EQ(l->call_name, "Sub1");
  l = &p("M1=3");
  EXPECT_EQ(l->items[0].kind, ItemKind::M);
  EXPECT_EQ(l->items[0].extension, 1);
}

TEST(LineParser, ControlStatements) {
  Parsed p;
  EXPECT_EQ(p("IF R1>2").statement, Statement::If);
  const auto& g = p("IF (R1>2) AND (R2<1) GOTOB N50");
  EXPECT_EQ(g.statement, Statement::IfGoto);
  EXPECT_EQ(g.jump, JumpDirection::Backward);
  EXPECT_EQ(*g.target.number, 50);
  EXPECT_EQ(p("ELSE").statement, Statement::Else);
  EXPECT_EQ(p("endif").statement, Statement::EndIf);
  EXPECT_EQ(p("WHILE R1<3").statement, Statement::While);
  const auto& f = p("FOR I=1 TO 10");
  EXPECT_EQ(f.statement, Statement::For);
  EXPECT_EQ(f.for_variable, "I");
  EXPECT_EQ(p("REPEAT").statement, Statement::Repeat);
  EXPECT_EQ(p("UNTIL R1==3").statement, Statement::Until);
  EXPECT_EQ(p("LOOP").statement, Statement::Loop);
  EXPECT_EQ(p("ENDLOOP").statement, Statement::EndLoop);
  const auto& j = p("GOTOF ende");
  EXPECT_EQ(j.statement, Statement::Goto);
  EXPECT_EQ(j.target.label, "ENDE");
  EXPECT_EQ(p("GOTOC X1").jump, JumpDirection::NoAlarm);
  EXPECT_EQ(p("GOTO X1").jump, JumpDirection::ForwardThenBackward);
  const auto& d = p("DEF REAL A=1, B, C=2*3");
  EXPECT_EQ(d.statement, Statement::Def);
  EXPECT_EQ(d.def_type, "REAL");
  EXPECT_EQ(d.defs.size(), 3u);
  EXPECT_EQ(p("DEF STRING[16] S=\"x\"").def_type, "STRING");
  const auto& pr = p("PROC CONTOUR(REAL DEPTH, INT N) SAVE");
  EXPECT_EQ(pr.statement, Statement::Proc);
  EXPECT_EQ(pr.defs.size(), 2u);
}

int error_of(const std::string& s) {
  Parsed p;
  try {
    p(s);
  } catch (const LineError& e) {
    return e.number();
  }
  return 0;
}

TEST(LineParser, SyntaxErrors) {
  EXPECT_EQ(error_of("X=(1+2"), 12080);
  EXPECT_EQ(error_of("X=1)"), 12080);
  EXPECT_EQ(error_of("CYCLE832(1,2"), 12080);
  EXPECT_EQ(error_of("G1 N10"), 12080);
  EXPECT_EQ(error_of("R5"), 12080);
  EXPECT_EQ(error_of("/10 X1"), 14060);
  EXPECT_EQ(error_of("M1: WHILE 1"), 12630);
  EXPECT_EQ(error_of("/ IF 1"), 12630);
  EXPECT_EQ(error_of("FOR R1=1"), 12080);
  EXPECT_EQ(error_of("DEF FOO X"), 12080);
  EXPECT_EQ(error_of("ENDIF X1"), 12080);
  EXPECT_EQ(error_of("G1.5"), 12080);
  EXPECT_EQ(error_of("A[1] X1"), 12080);  // an array element needs '=' (only axis commands go without)
}

TEST(LineParser, AxisIndexedCommandsWithoutValue) {
  // DIAMONA[X], SCC[X] (Fundamentals, diameter programming and G96): a name with an axis index.
  Parsed p;
  const ParsedLine& line = p("DIAMONA[X] SCC[Z] G0 X40");
  ASSERT_EQ(line.items.size(), 4u);
  EXPECT_EQ(line.items[0].kind, ItemKind::Name);
  EXPECT_EQ(line.items[0].name, "DIAMONA");
  EXPECT_EQ(line.items[0].index_count, 1u);
  EXPECT_EQ(line.items[1].kind, ItemKind::Name);
  EXPECT_EQ(line.items[1].name, "SCC");
}

}  // namespace
}  // namespace drycut::parser

namespace drycut::parser {
namespace {

// Job Planning, "Definition and initialization of array variables": dimensions and value lists.
TEST(LineParserLanguage, DefArrayWithSetAndRep) {
  LineParser parser;
  ParsedLine l;
  const std::string a = "DEF INT AR[2,3]=SET(1,2,3), BR[4]=REP(7)";
  parser.parse(a, l);
  EXPECT_EQ(l.statement, Statement::Def);
  EXPECT_EQ(l.def_type, "INT");
  ASSERT_EQ(l.defs.size(), 2u);
  EXPECT_EQ(l.defs[0].name, "AR");
  EXPECT_EQ(l.defs[0].rank, 2);
  EXPECT_EQ(l.defs[0].init_kind, InitKind::List);
  EXPECT_EQ(l.defs[0].init_count, 3u);
  EXPECT_EQ(l.defs[1].rank, 1);
  EXPECT_EQ(l.defs[1].init_kind, InitKind::Rep);
  EXPECT_DOUBLE_EQ(l.pool[l.defs[1].init].value, 7.0);
}

// Job Planning, "Program branches (CASE ... OF ... DEFAULT ...)": branches in order, DEFAULT last.
TEST(LineParserLanguage, CaseBranchesAndDefault) {
  LineParser parser;
  ParsedLine l;
  const std::string a = "CASE(R1) OF 1 GOTOF LAB1 2 GOTOB LAB2 DEFAULT GOTOF LABD";
  parser.parse(a, l);
  EXPECT_EQ(l.statement, Statement::Case);
  ASSERT_EQ(l.cases.size(), 3u);
  EXPECT_DOUBLE_EQ(l.pool[l.cases[0].value].value, 1.0);
  EXPECT_EQ(l.cases[0].target.label, "LAB1");
  EXPECT_EQ(l.cases[1].jump, JumpDirection::Backward);
  EXPECT_EQ(l.cases[2].value, kNoExpr);
  EXPECT_EQ(l.cases[2].target.label, "LABD");
}

// Job Planning, "Program section repetition": REPEAT start [end] [P=n], REPEATB label [P=n].
TEST(LineParserLanguage, RepeatSectionForms) {
  LineParser parser;
  ParsedLine l;
  const std::string a = "REPEAT SEC_A SEC_B P=2";
  parser.parse(a, l);
  EXPECT_EQ(l.statement, Statement::RepeatSection);
  EXPECT_EQ(l.call_name, "SEC_A");
  EXPECT_EQ(l.end_label, "SEC_B");
  EXPECT_FALSE(l.repeat_one_block);
  EXPECT_DOUBLE_EQ(l.pool[l.passes].value, 2.0);
  const std::string b = "REPEATB ONE P=4";
  parser.parse(b, l);
  EXPECT_EQ(l.statement, Statement::RepeatSection);
  EXPECT_TRUE(l.repeat_one_block);
  EXPECT_EQ(l.call_name, "ONE");
  const std::string c = "REPEAT";  // alone: the REPEAT ... UNTIL loop
  parser.parse(c, l);
  EXPECT_EQ(l.statement, Statement::Repeat);
}

}  // namespace
}  // namespace drycut::parser
