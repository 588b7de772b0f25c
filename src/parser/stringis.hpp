#pragma once
// STRINGIS(name): what the NC language knows a name as (Function Manual Basic Functions, K1,
// "STRINGIS"). The answer is a three-digit code yxx:
//   0    not an element of the language (also an address letter with a wrong extension, M02)
//   2xx  a programmable element, xx its kind:
//        01 DIN/NC address A B C E I J K Q U V W X Y Z, with or without an extension (A1)
//        02 G command (G04, SOFT, ASPLINE, INVCW ...)
//        03 function with a return value (SIN, STRLEN ...)
//        05 keyword (DEFINE, WHILE ...)
//        06 machine, setting or option datum ($M..., $S..., $O...)
//        07 system variable ($...) or R parameter (R10)
//        08 cycle (a program file the control has loaded)
//        09 GUD variable, 10 macro, 11 LUD variable of the running program
//   400  one of the user-defined address letters D F H L M N O P S T alone (no extension)
// drycut's command table does not tell G commands from procedures without a return value
// (code 204): every named command answers 202. Code 100 (known but option inactive) and 212
// (ISO G command in ISO mode) never occur: drycut has no options and no ISO mode.
#include <functional>
#include <string_view>

namespace drycut::parser {

// What the running program knows beyond the language tables.
struct StringIsContext {
  std::function<bool(std::string_view)> is_macro;
  std::function<bool(std::string_view)> is_local_variable;
  std::function<bool(std::string_view)> is_global_variable;
  std::function<bool(std::string_view)> is_program_file;
};

// `upper_name` in upper case.
int stringis_code(std::string_view upper_name, const StringIsContext& context);

}  // namespace drycut::parser
