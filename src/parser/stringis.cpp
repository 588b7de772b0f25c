#include "parser/stringis.hpp"

#include <algorithm>

#include "parser/command_table.hpp"
#include "parser/expression_parser.hpp"
#include "parser/function_table.hpp"
#include "parser/system_variables.hpp"

namespace drycut::parser {
namespace {

bool all_digits(std::string_view s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

bool is_language_keyword(std::string_view name) {
  static constexpr std::string_view kKeywords[] = {
      "DEF", "DEFINE", "AS", "PROC", "EXTERN", "IF", "ELSE", "ENDIF", "WHILE", "ENDWHILE", "FOR",
      "TO", "ENDFOR", "REPEAT", "UNTIL", "LOOP", "ENDLOOP", "CASE", "OF", "DEFAULT", "GOTO",
      "GOTOF", "GOTOB", "GOTOC", "GOTOS", "CALL", "PCALL", "MCALL", "RET", "SAVE", "DISPLOF",
      "DISPLON", "REPEATB", "INT", "REAL", "BOOL", "CHAR", "STRING", "AXIS", "FRAME", "VAR",
      "WHEN", "WHENEVER", "DO", "ID", "IDS", "SETINT", "ENABLE", "DISABLE", "CLRINT", "STOPRE"};
  return std::find(std::begin(kKeywords), std::end(kKeywords), name) != std::end(kKeywords);
}

}  // namespace

int stringis_code(std::string_view name, const StringIsContext& context) {
  if (name.empty()) return 0;
  if (context.is_macro && context.is_macro(name)) return 210;
  if (context.is_local_variable && context.is_local_variable(name)) return 211;
  if (context.is_global_variable && context.is_global_variable(name)) return 209;
  const std::string_view rest = name.substr(1);
  if (name[0] == '$') {
    if (name.size() > 1 && (name[1] == 'M' || name[1] == 'S' || name[1] == 'O')) return 206;
    return classify_system_variable(name) != SystemVariableClass::Unknown ? 207 : 0;
  }
  if (std::string_view("ABCEIJKQUVWXYZ").find(name[0]) != std::string_view::npos &&
      (rest.empty() || all_digits(rest)))
    return 201;
  if (name.size() == 1 && std::string_view("DFHLMNOPST").find(name[0]) != std::string_view::npos) return 400;
  if (name[0] == 'R' && all_digits(rest)) return 207;
  if (name[0] == 'G' && all_digits(rest)) {
    const Support s = g_code_support(std::stoll(std::string(rest)));
    return s == Support::Unknown ? 0 : 202;
  }
  if (is_language_keyword(name)) return 205;
  if (const FunctionInfo* f = find_function(name)) {
    // The position modes and value lists are no functions of their own in the manual's sense
    // but words of the language.
    return f->func == Function::ArraySet || f->func == Function::ArrayRep ? 205 : 203;
  }
  if (context.is_program_file && context.is_program_file(name)) return 208;
  if (command_support(name) != Support::Unknown) return 202;
  return 0;
}

}  // namespace drycut::parser
