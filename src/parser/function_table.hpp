#pragma once
// The one table of the language's functions (name, arity, meaning): the expression parser
// resolves names through it and docs/language.md is generated from it.
#include <cstdint>
#include <span>
#include <string_view>

#include "parser/expression.hpp"

namespace drycut::parser {

struct FunctionInfo {
  std::string_view name;
  Function func;
  uint8_t min_args;
  uint8_t max_args;
  std::string_view meaning;  // one line for the language table
};

const FunctionInfo* find_function(std::string_view upper_name);
std::span<const FunctionInfo> all_functions();

}  // namespace drycut::parser
