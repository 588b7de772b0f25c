// docs/language.md is `drycut language --markdown`: generated from the tables the parser decides
// with, so it cannot drift. And what issue 11 listed as refused is in the table now.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "parser/command_table.hpp"
#include "parser/function_table.hpp"
#include "parser/language_table.hpp"

namespace {

using drycut::parser::Support;

TEST(LanguageTable, DocsLanguageMdIsTheGeneratedTable) {
  std::ifstream in(std::string(DRYCUT_SOURCE_DIR) + "/docs/language.md");
  ASSERT_TRUE(in) << "docs/language.md missing";
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), drycut::parser::language_markdown())
      << "docs/language.md is out of date: build/drycut language --markdown > docs/language.md";
}

TEST(LanguageTable, NothingOfTheLanguageIssueIsRefused) {
  for (const char* f : {"ROUNDUP", "TRUNC", "ROUND", "MINVAL", "MAXVAL", "BOUND", "POT", "LN", "EXP", "ATAN2", "STRLEN",
                        "INDEX", "RINDEX", "MINDEX", "SUBSTR", "TOUPPER", "TOLOWER", "NUMBER", "ISNUMBER", "ISVAR",
                        "SPRINT", "AXNAME", "AXSTRING", "GETT"})
    EXPECT_NE(drycut::parser::find_function(f), nullptr) << f;
  for (const char* c : {"SBLOF", "SBLON", "DRFOF", "DISPLOF", "DISPLON", "STOPRE", "MSG", "TRAORI", "COMPCAD", "FFWON"})
    EXPECT_NE(drycut::parser::command_support(c), Support::Unknown) << c;
  const auto features = drycut::parser::language_features();
  for (const char* s : {"CASE expr OF c GOTOx l ... DEFAULT GOTOx l", "EXTERN name(types)", "DEFINE name AS text",
                        "SETAL(n[, text])", "ID=n WHEN/WHENEVER/FROM/EVERY ... DO ...",
                        "SETINT(n) PRIO=m NAME / ENABLE / DISABLE / CLRINT", "REPEAT start [end] P=n / REPEATB label P=n / ENDLABEL:"}) {
    bool found = false;
    for (const auto& f : features)
      if (f.name == s) found = f.support != Support::Unknown;
    EXPECT_TRUE(found) << s;
  }
  for (const auto& f : features) EXPECT_NE(f.support, Support::Unknown) << f.name;
}

}  // namespace
