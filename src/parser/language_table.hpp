#pragma once
// The language as one table: every statement, command, G code, function, address and class of
// system variable drycut knows, with what it does with it (modelled / modelled by doing nothing
// / accepted with a warning). It is built from the tables the parser itself decides with
// (command_table, function_table, the statements below, the system-variable registry), so
// docs/language.md, which `drycut language --markdown` writes, cannot drift from the code.
// Anything not in the table is refused (with the control's alarm: 12550, 12470, 12080 ...).
#include <string>
#include <vector>

#include "parser/command_table.hpp"

namespace drycut::parser {

struct LanguageFeature {
  std::string section;  // "Statements", "Commands", "G codes", ...
  std::string name;
  Support support = Support::Modelled;
  std::string meaning;
};

std::vector<LanguageFeature> language_features();
std::string_view support_text(Support s);
// docs/language.md
std::string language_markdown();

}  // namespace drycut::parser
