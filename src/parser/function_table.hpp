#pragma once
// The one table of the language's functions (name, arity, meaning): the expression parser
// resolves names through it and docs/language.md is generated from it.
#include <cstdint>
#include <span>
#include <string_view>

#include "parser/expression.hpp"
#include "parser/value.hpp"

namespace drycut::parser {

struct FunctionInfo {
  std::string_view name;
  Function func;
  uint8_t min_args;
  uint8_t max_args;
  std::string_view meaning;  // one line for the language table
  // Function::Assumed: the result drycut assumes, the one a call that went well gives ("TRUE",
  // "0", "FRAME" = the null frame, "\"\"" = the empty string); warning 990002 names it.
  std::string_view assumed = {};
};

// The value FunctionInfo::assumed stands for.
Value assumed_result(const FunctionInfo& f);

const FunctionInfo* find_function(std::string_view upper_name);
std::span<const FunctionInfo> all_functions();

}  // namespace drycut::parser
