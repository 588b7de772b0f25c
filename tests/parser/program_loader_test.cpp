#include "parser/program_loader.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

namespace drycut::parser {
namespace {

namespace fs = std::filesystem;

class Loader : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("drycut_loader_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_ / "lib");
  }
  void TearDown() override { fs::remove_all(dir_); }
  void write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name, std::ios::binary) << text;
  }
  // Runs MAIN.MPF; returns the executed blocks as "file-stem:line:text".
  std::vector<Block> run(const std::string& main_text, LoaderOptions options = {}) {
    write("MAIN.MPF", main_text);
    options.search_path.push_back(dir_ / "lib");
    loader_ = std::make_unique<ProgramLoader>(options, diagnostics_);
    loader_->open_main(dir_ / "MAIN.MPF");
    std::vector<Block> out;
    Block b;
    while (loader_->next(b)) out.push_back(b);
    return out;
  }
  static std::vector<double> xs(const std::vector<Block>& blocks) {
    std::vector<double> v;
    for (const auto& b : blocks)
      if (const auto* a = b.find_address("X")) v.push_back(a->value);
    return v;
  }
  int alarm_of(const std::string& main_text, LoaderOptions options = {}) {
    try {
      run(main_text, options);
    } catch (const AlarmError& e) {
      last_alarm_ = e.alarm();
      return e.alarm().number;
    }
    return 0;
  }
  fs::path dir_;
  Diagnostics diagnostics_;
  std::unique_ptr<ProgramLoader> loader_;
  Alarm last_alarm_;
};

TEST_F(Loader, EmitsEvaluatedBlocksWithLocation) {
  const auto b = run("; header\nN10 G1 X=2*3 Y-1.5 F1500 ; cut\n\nR1=4\nX=R1*2 Z=AC(1) Y=IC(-1)\nM30\n");
  ASSERT_EQ(b.size(), 3u);
  EXPECT_EQ(b[0].line, 2u);
  EXPECT_EQ(*b[0].number, 10);
  EXPECT_EQ(b[0].text, "N10 G1 X=2*3 Y-1.5 F1500 ; cut");
  EXPECT_TRUE(b[0].has_g(1));
  EXPECT_DOUBLE_EQ(b[0].find_address("X")->value, 6.0);
  EXPECT_DOUBLE_EQ(b[0].find_address("Y")->value, -1.5);
  EXPECT_EQ(b[0].find_address("X")->column, 8u);
  EXPECT_DOUBLE_EQ(b[1].find_address("X")->value, 8.0);
  EXPECT_EQ(b[1].find_address("Z")->mode, ValueMode::Absolute);
  EXPECT_EQ(b[1].find_address("Y")->mode, ValueMode::Incremental);
  EXPECT_DOUBLE_EQ(b[1].find_address("Y")->value, -1.0);
  EXPECT_TRUE(b[2].has_m(30));
  EXPECT_EQ(loader_->blocks_executed(), 3u);
}

TEST_F(Loader, CommandsToolNamesAndArguments) {
  const auto b = run("T=\"Fr_4\" D1\nASPLINE BTAN MSG(\"Go\") SPLINEPATH(1,X,Y)\nM30\n");
  ASSERT_EQ(b.size(), 3u);
  EXPECT_EQ(*b[0].tool_name, "Fr_4");
  ASSERT_EQ(b[1].commands.size(), 4u);
  EXPECT_DOUBLE_EQ(std::get<double>(b[1].find_command("SPLINEPATH")->args[0]), 1.0);
  EXPECT_EQ(std::get<std::string>(b[1].find_command("MSG")->args[0]), "Go");
  EXPECT_EQ(std::get<std::string>(b[1].find_command("SPLINEPATH")->args[2]), "Y");
}

TEST_F(Loader, NotModelledCommandWarnsAndIsDropped) {
  const auto b = run("G1 X1 F100 CUT3DC\nSETPIECE(1)\nM30\n");
  ASSERT_EQ(b.size(), 2u);
  EXPECT_TRUE(b[0].commands.empty());
  ASSERT_EQ(diagnostics_.items().size(), 2u);
  EXPECT_EQ(diagnostics_.items()[0].number, 990002);
  EXPECT_EQ(diagnostics_.items()[0].where.line, 1u);
  EXPECT_EQ(diagnostics_.items()[0].where.column, 12u);
  EXPECT_EQ(diagnostics_.items()[1].where.line, 2u);
}

TEST_F(Loader, TransformationIsWarnedAndStillHandedOn) {
  // TRANSMIT is not modelled (990002), but the interpreter needs it: it does not check
  // software limits on the programmed axes while a transformation is on; TRAFOOF (silent, it
  // changes nothing else drycut models) brings the checks back (docs/axes.md).
  const auto b = run("TRANSMIT\nG1 X1 F100\nTRAFOOF\nM30\n");
  ASSERT_EQ(b.size(), 4u);
  ASSERT_NE(b[0].find_command("TRANSMIT"), nullptr);
  ASSERT_NE(b[2].find_command("TRAFOOF"), nullptr);
  ASSERT_EQ(diagnostics_.items().size(), 1u);
  EXPECT_EQ(diagnostics_.items()[0].number, 990002);
}

// Standard cycles are ordinary subprogram calls: the first folder of the search path that
// holds CYCLE81.SPF wins (drycut's own cycles come last, the user's folders first).
TEST_F(Loader, StandardCycleIsASubprogramCall) {
  fs::create_directories(dir_ / "user");
  write("user/CYCLE81.SPF", "PROC CYCLE81(REAL RTP, REAL RFP, REAL SDIS, REAL DP)\nG1 Z=DP\nM17\n");
  write("lib/CYCLE81.SPF", "PROC CYCLE81(REAL RTP, REAL RFP, REAL SDIS, REAL DP)\nG1 Z=RTP\nM17\n");
  LoaderOptions options;
  options.search_path.push_back(dir_ / "user");  // run() appends lib (the "shipped" one) after it
  std::vector<Block> b = run("G1 X1 F100\nCYCLE81(10,0,2,-5)\nM30\n", options);
  ASSERT_EQ(b.size(), 4u);  // G1 X1, the cycle's G1 Z, its M17, M30
  EXPECT_DOUBLE_EQ(b[1].find_address("Z")->value, -5.0);
  EXPECT_TRUE(diagnostics_.items().empty());
}

TEST_F(Loader, SubprogramByEveryNameFormAndCase) {
  write("lib/EKVI_POSTUPNE_45.SPF", "G1 X1\nM17\n");
  write("lib/sub_b.spf", "G1 X2\nRET\n");
  write("lib/_N_SUBC_SPF.SPF", "G1 X3\nM17\n");
  write("lib/L77.SPF", "G1 X4\nM17\n");
  write("MAINSUB.SPF", "G1 X5\n");  // main folder first, no M17: end of file returns
  const auto b = run(
      "ekvi_postupne_45\nSUB_B.SPF\n_N_SUBC_SPF\nL77\nCALL \"subc\"\nMAINSUB\nM30\n");
  EXPECT_EQ(xs(b), (std::vector<double>{1, 2, 3, 4, 3, 5}));
  EXPECT_EQ(b[0].program_level, 1);
  EXPECT_NE(b[0].file->find("EKVI_POSTUPNE_45.SPF"), std::string::npos);
  EXPECT_EQ(b.back().program_level, 0);
  EXPECT_EQ(loader_->programs_used(),
            (std::vector<std::string>{"MAIN", "EKVI_POSTUPNE_45", "SUB_B", "SUBC", "L77", "MAINSUB"}));
}

TEST_F(Loader, PassesCountAndLocalsResetPerPass) {
  write("lib/REP.SPF", "DEF INT K=1\nR1=R1+K\nG1 X=R1\nM17\n");
  const auto b = run("REP P3\nM30\n");
  EXPECT_EQ(xs(b), (std::vector<double>{1, 2, 3}));
}

TEST_F(Loader, ProcParametersAreBound) {
  write("lib/DEPTH.SPF", "PROC DEPTH(REAL Z0, INT N)\nG1 X=Z0*N\nRET\n");
  const auto b = run("DEPTH(1.5, 4)\nM30\n");
  EXPECT_EQ(xs(b), (std::vector<double>{6}));
}

TEST_F(Loader, SixteenLevelsAllowedSeventeenRejected) {
  // LEVn calls LEV(n+1); the deepest prints its level.
  for (int i = 1; i <= 16; ++i)
    write("lib/LEV" + std::to_string(i) + ".SPF",
          i < 16 ? "LEV" + std::to_string(i + 1) + "\nM17\n" : "G1 X16\nM17\n");
  write("lib/DEEP.SPF", "LEV2\nM17\n");
  EXPECT_EQ(alarm_of("LEV2\nM30\n"), 0);  // main + LEV2..LEV16 = 16 levels
  EXPECT_EQ(alarm_of("LEV1\nM30\n"), 990003);
}

TEST_F(Loader, IfElseEndif) {
  const auto b = run("R1=2\nIF R1==2\nX1\nELSE\nX2\nENDIF\nIF R1<>2\nX3\nELSE\nX4\nENDIF\nIF 0\nX5\nENDIF\nM30\n");
  EXPECT_EQ(xs(b), (std::vector<double>{1, 4}));
}

TEST_F(Loader, NestedIfInsideSkippedBranch) {
  const auto b = run("IF 0\nIF 1\nX1\nELSE\nX2\nENDIF\nELSE\nX3\nENDIF\nM30\n");
  EXPECT_EQ(xs(b), (std::vector<double>{3}));
}

TEST_F(Loader, WhileForRepeatLoop) {
  const auto b = run(
      "DEF INT I\nR1=0\nWHILE R1<3\nR1=R1+1\nX=R1\nENDWHILE\n"
      "FOR I=1 TO 3\nX=10*I\nENDFOR\n"
      "FOR R2=5 TO 4\nX99\nENDFOR\n"
      "REPEAT\nR1=R1-1\nX=R1\nUNTIL R1<=1\n"
      "R3=0\nLOOP\nR3=R3+1\nIF R3>2 GOTOF OUT\nX=100+R3\nENDLOOP\nOUT: M30\n");
  EXPECT_EQ(xs(b), (std::vector<double>{1, 2, 3, 10, 20, 30, 2, 1, 101, 102}));
}

TEST_F(Loader, NestedLoopsWithJumpOutOfInner) {
  const auto b = run(
      "R1=0\nWHILE R1<2\nR1=R1+1\nR2=0\nWHILE 1\nR2=R2+1\nIF R2>=2 GOTOF NEXT\nENDWHILE\nNEXT: X=R1*10+R2\nENDWHILE\nM30\n");
  EXPECT_EQ(xs(b), (std::vector<double>{12, 22}));
}

TEST_F(Loader, JumpsToLabelsAndBlockNumbers) {
  const auto b = run(
      "GOTOF N40\nX1\nN40 X2\nR1=0\nBACK: R1=R1+1\nX=R1+10\nIF R1<3 GOTOB BACK\n"
      "GOTO FWD\nX3\nFWD: X4\nR2=0\nAGAIN: R2=R2+1\nIF R2==2 GOTOF DONE\nGOTO AGAIN\nDONE: GOTOC NOWHERE\nX5\nM30\n");
  EXPECT_EQ(xs(b), (std::vector<double>{2, 11, 12, 13, 4, 5}));
}

TEST_F(Loader, GotobToBlockNumberSearchesFromFileStart) {
  const auto b = run("N10 R1=R1+1\nX=R1\nIF R1<2 GOTOB N10\nM30\n");
  EXPECT_EQ(xs(b), (std::vector<double>{1, 2}));
}

TEST_F(Loader, StepLimitStopsEndlessLoop) {
  LoaderOptions o;
  o.max_steps = 50;
  EXPECT_EQ(alarm_of("L: X1\nGOTOB L\n", o), 990004);
}

TEST_F(Loader, LoopWaitingForAnInputEndsAtOnce) {
  // The same loop without an input read is endless (990004); reading $A_IN makes it a wait
  // that is left at the first repeat, each form by not taking its jump back.
  EXPECT_EQ(alarm_of("R1=0\nWHILE R1==0\nENDWHILE\nM30\n"), 990004);
  EXPECT_EQ(xs(run("WHILE $A_IN[1]==0\nENDWHILE\nX1\nW: IF $A_IN[2]==0 GOTOB W\nX2\n"
                   "REPEAT\nX3\nUNTIL $A_IN[3]==1\nX4\nM30\n")),
            (std::vector<double>{1, 2, 3, 3, 4}));  // REPEAT's body runs twice before the repeat is seen
}

TEST_F(Loader, SkipLevels) {
  LoaderOptions o;
  o.skip_levels_active[0] = true;
  o.skip_levels_active[2] = true;
  EXPECT_EQ(xs(run("/X1\n/1 X2\n/2 X3\nX4\nM30\n", o)), (std::vector<double>{2, 4}));
  EXPECT_EQ(xs(run("/X1\n/1 X2\nM30\n")), (std::vector<double>{1, 2}));  // default: all executed
}

TEST_F(Loader, M2AndM30InASubprogramReturnToTheCaller) {
  // Fundamentals, "Subprograms": a subprogram, like a main program, may end with M2; there it
  // means the return to the calling level (as M17/RET). M30 likewise.
  write("lib/ENDS_M2.SPF", "X1\nM2\nX2\n");
  write("lib/ENDS_M30.MPF", "X4\nM30\n");
  EXPECT_EQ(xs(run("ENDS_M2\nX3\nENDS_M30\nX5\nM30\nX6\n")), (std::vector<double>{1, 3, 4, 5}));
}

TEST_F(Loader, CrlfAndLatin1Files) {
  const auto b = run("; Fr\xE4se\r\nG1 X1 ; \xDC\r\nMSG(\"M\xFC\")\r\nM30\r\n");
  ASSERT_EQ(b.size(), 3u);
  EXPECT_EQ(b[0].text, "G1 X1 ; \xC3\x9C");
  EXPECT_EQ(std::get<std::string>(b[1].commands[0].args[0]), "M\xC3\xBC");
  EXPECT_EQ(b[2].line, 4u);
}

TEST_F(Loader, DefVariablesAndTypes) {
  const auto b = run("DEF INT N=2.6\nDEF BOOL OK=5\nDEF REAL A\nA=N/2\nX=A Y=OK\nM30\n");
  EXPECT_DOUBLE_EQ(b[0].find_address("X")->value, 1.5);  // INT rounds 2.6 to 3
  EXPECT_DOUBLE_EQ(b[0].find_address("Y")->value, 1.0);
}

TEST_F(Loader, AlarmsCarryFileLineColumnAndBlock) {
  EXPECT_EQ(alarm_of("G1 X1\nN20 X=1+R1/0\n"), 14051);
  EXPECT_EQ(last_alarm_.where.line, 2u);
  EXPECT_EQ(last_alarm_.where.column, 11u);
  EXPECT_EQ(last_alarm_.block, "N20 X=1+R1/0");
  EXPECT_NE(last_alarm_.where.file.find("MAIN.MPF"), std::string::npos);
  EXPECT_EQ(alarm_of("ASPLIN\n"), 12550);
  EXPECT_EQ(alarm_of("NOTTHERE\n"), 14011);
  EXPECT_EQ(alarm_of("GOTOF X\n"), 14080);
  EXPECT_EQ(alarm_of("WHILE 1\nX1\n"), 12640);
  EXPECT_EQ(alarm_of(""), 990010);
}

TEST_F(Loader, DefinitionFileAlarmNamesTheFileAndComesFromNext) {
  // An alarm in a *.DEF beside the main program: raised by next() (where callers handle the
  // program's alarms; from open_main it escaped `run` as an internal error) and located in the
  // definition file, not in "<program>".
  write("UGUD.DEF", "DEF NCK REAL A\nDEF NCK REAL A\n");
  write("MAIN.MPF", "G1 X1\nM30\n");
  loader_ = std::make_unique<ProgramLoader>(LoaderOptions{}, diagnostics_);
  ASSERT_NO_THROW(loader_->open_main(dir_ / "MAIN.MPF"));
  Block b;
  try {
    loader_->next(b);
    FAIL() << "no alarm";
  } catch (const AlarmError& e) {
    EXPECT_EQ(e.alarm().number, 12170);
    EXPECT_EQ(fs::path(e.alarm().where.file).filename(), "UGUD.DEF");
    EXPECT_EQ(e.alarm().where.line, 2u);
  }
}

TEST_F(Loader, MachineDefinitionFilesDefineDrycutsStandardNamesAgain) {
  // drycut's own definition folder (the first standard_definition_dirs of definition_dirs)
  // defines _TSA and _FINISH; the machine's own files, read after it, define them again: their
  // definitions are in force. A name defined twice by the machine's own files stays 12170 (above).
  fs::create_directories(dir_ / "std");
  fs::create_directories(dir_ / "machine");
  write("std/GUD.DEF", "DEF CHAN REAL _TSA=1\nDEFINE _FINISH AS 1\nM17\n");
  write("machine/GUD.DEF", "DEF CHAN REAL _TSA=7\nDEFINE _FINISH AS 2\nM17\n");
  LoaderOptions options;
  options.definition_dirs = {dir_ / "std", dir_ / "machine"};
  options.standard_definition_dirs = 1;
  EXPECT_EQ(xs(run("X=_TSA\nX=_FINISH\nM30\n", options)), (std::vector<double>{7, 2}));
  // Without the mark the second DEF is one definition too many.
  options.standard_definition_dirs = 0;
  EXPECT_EQ(alarm_of("X=_TSA\nM30\n", options), 12170);
  // A folder named twice (also the main program's own) is read once.
  write("GUD.DEF", "DEF CHAN REAL _TSB=3\nM17\n");
  options.definition_dirs = {dir_, dir_ / "machine"};
  EXPECT_EQ(xs(run("X=_TSB\nM30\n", options)), (std::vector<double>{3}));
}

TEST_F(Loader, HeaderAfterABomAndCommentLinesStartsTheProgram) {
  // Notepad-style editors write a UTF-8 BOM; DNC software adds a comment line before the header.
  EXPECT_EQ(xs(run("\xEF\xBB\xBF; part 4711\n\n%_N_MAIN_MPF\n;$PATH=/_N_MPF_DIR\nG1 X1 F100\nX2\nM30\n")),
            (std::vector<double>{1, 2}));
}

TEST_F(Loader, MissingMainIsUsageError) {
  ProgramLoader l({}, diagnostics_);
  EXPECT_THROW(l.open_main(dir_ / "NOPE.MPF"), UsageError);
}

}  // namespace
}  // namespace drycut::parser
