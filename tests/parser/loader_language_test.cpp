// Language rules of the loader found by the conformance suite (tests/conformance/language):
// array value lists in assignments, characters of strings, STRING -> BOOL, CASE, REPEAT.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "parser/program_loader.hpp"

namespace drycut::parser {
namespace {

namespace fs = std::filesystem;

class LoaderLanguage : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("drycut_lang_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  // Runs the program; returns the X values of the executed blocks in order.
  std::vector<double> xs(const std::string& text, LoaderOptions options = {}) {
    std::ofstream(dir_ / "MAIN.MPF", std::ios::binary) << text;
    ProgramLoader loader(options, diagnostics_);
    loader.open_main(dir_ / "MAIN.MPF");
    std::vector<double> out;
    Block b;
    while (loader.next(b))
      if (const auto* a = b.find_address("X")) out.push_back(a->value);
    return out;
  }
  int alarm_of(const std::string& text) {
    try {
      xs(text);
    } catch (const AlarmError& e) {
      return e.alarm().number;
    }
    return 0;
  }
  fs::path dir_;
  Diagnostics diagnostics_;
};

// Job Planning, "Definition and initialization of array variables": SET writes consecutive
// elements from the given one, REP fills from the given one to the end.
TEST_F(LoaderLanguage, SetAndRepInAssignments) {
  const auto x = xs("DEF INT AR[4]\nAR[1]=SET(5,6)\nX=AR[0]+AR[1]*10+AR[2]*100\nAR[2]=REP(9)\nX=AR[1]+AR[2]*10+AR[3]*100\nM30\n");
  ASSERT_EQ(x.size(), 2u);
  EXPECT_DOUBLE_EQ(x[0], 0 + 50 + 600);
  EXPECT_DOUBLE_EQ(x[1], 5 + 90 + 900);
}

TEST_F(LoaderLanguage, SetPastTheEndAndSetInAnExpressionAreRefused) {
  EXPECT_EQ(alarm_of("DEF INT AR[3]\nAR[2]=SET(1,2)\nM30\n"), 17020);
  EXPECT_EQ(alarm_of("R1=SET(1,2)+1\nM30\n"), 12080);
}

// Job Planning, "Read and write individual characters": STRING[i] is the character at i (from 0).
TEST_F(LoaderLanguage, CharactersOfAString) {
  const auto x = xs("DEF STRING[8] SV=\"ABC\"\nDEF CHAR CH\nCH=SV[2]\nSV[1]=\"X\"\nX=CH\nX=INDEX(SV,\"X\")\nX=SV[0]==\"A\"\nM30\n");
  ASSERT_EQ(x.size(), 3u);
  EXPECT_DOUBLE_EQ(x[0], 'C');
  EXPECT_DOUBLE_EQ(x[1], 1);
  EXPECT_DOUBLE_EQ(x[2], 1);
  EXPECT_EQ(alarm_of("DEF STRING[8] SV=\"ABC\"\nR1=SV[3]\nM30\n"), 17020);
}

// Job Planning, "Type conversion": a STRING becomes FALSE when empty, TRUE otherwise.
TEST_F(LoaderLanguage, StringToBool) {
  const auto x = xs("DEF BOOL B1, B2\nDEF STRING[4] S1\nB1=S1\nB2=\"Q\"\nX=B1\nX=B2\nM30\n");
  ASSERT_EQ(x.size(), 2u);
  EXPECT_DOUBLE_EQ(x[0], 0);
  EXPECT_DOUBLE_EQ(x[1], 1);
}

// Job Planning, "Program branches (CASE ... OF ... DEFAULT ...)".
TEST_F(LoaderLanguage, CaseJumpsToTheMatchingLabelOrDefault) {
  const std::string body = "CASE(R1) OF 1 GOTOF LA1 2 GOTOF LA2 DEFAULT GOTOF LD\nLA1: X1\nGOTOF EE\nLA2: X2\nGOTOF EE\nLD: X9\nEE: M30\n";
  EXPECT_EQ(xs("R1=2\n" + body), std::vector<double>{2});
  EXPECT_EQ(xs("R1=7\n" + body), std::vector<double>{9});
}

// Job Planning, "Program section repetition": REPEAT label P=n runs the section n more times.
TEST_F(LoaderLanguage, RepeatSectionRunsPMoreTimes) {
  const auto x = xs("R1=0\nST: R1=R1+1\nX=R1\nREPEAT ST P=2\nM30\n");
  EXPECT_EQ(x, (std::vector<double>{1, 2, 3}));
}

// Job Planning, "Indirect subprogram call (CALL)": the name may come from a STRING variable.
TEST_F(LoaderLanguage, CallTakesTheNameFromAStringVariable) {
  std::ofstream(dir_ / "SUB_B.SPF", std::ios::binary) << "PROC SUB_B\nX7\nM17\n";
  EXPECT_EQ(xs("DEF STRING[10] PN=\"SUB_B\"\nCALL PN\nM30\n"), std::vector<double>{7});
}

// More call arguments than PROC parameters: alarm 12340.
TEST_F(LoaderLanguage, TooManyArgumentsAreRefused) {
  std::ofstream(dir_ / "SUB_C.SPF", std::ios::binary) << "PROC SUB_C(REAL PA)\nX=PA\nM17\n";
  EXPECT_EQ(xs("SUB_C(4)\nM30\n"), std::vector<double>{4});
  EXPECT_EQ(alarm_of("SUB_C(4, 5)\nM30\n"), 12340);
}

// LUD by default: a subprogram does not see the main program's variables (12550); with
// MD11120 LUD_EXTENDED_SCOPE = 1 they are program-global (PUD) and it does.
TEST_F(LoaderLanguage, MainProgramVariablesAreSeenInSubprogramsOnlyWithLudExtendedScope) {
  std::ofstream(dir_ / "SUB_PUD.SPF", std::ios::binary) << "G0 X=DEPTH+1\nM17\n";
  const std::string main = "DEF REAL DEPTH=4\nSUB_PUD\nM30\n";
  EXPECT_EQ(alarm_of(main), 12550);
  LoaderOptions pud;
  pud.machine_data["$MN_LUD_EXTENDED_SCOPE"] = 1;
  EXPECT_EQ(xs(main, pud), std::vector<double>{5.0});
}

// An endless loop whose state repeats is found at the second visit, not at the step limit.
TEST_F(LoaderLanguage, EndlessLoopWithUnchangedStateIsFoundAtOnce) {
  LoaderOptions options;
  options.max_steps = 1'000'000'000;
  try {
    xs("R1=0\nLBL: G0 X=R1\nR2=R1\nGOTOB LBL\nM30\n", options);
    FAIL() << "no alarm";
  } catch (const AlarmError& e) {
    EXPECT_EQ(e.alarm().number, 990004);
    EXPECT_EQ(e.alarm().where.line, 4u);
  }
  // A loop that changes its counter is no endless loop: it ends by its condition.
  EXPECT_EQ(xs("R1=0\nLBL: R1=R1+1\nIF R1<1000 GOTOB LBL\nG0 X=R1\nM30\n", options), std::vector<double>{1000.0});
}

}  // namespace
}  // namespace drycut::parser
