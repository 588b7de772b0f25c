#include "parser/value.hpp"

#include <array>
#include <cmath>
#include <cstdio>

namespace drycut::parser {
namespace {

struct TypeName {
  std::string_view name;
  DataType type;
};
constexpr std::array kTypeNames{TypeName{"INT", DataType::Int},       TypeName{"REAL", DataType::Real},
                                TypeName{"BOOL", DataType::Bool},     TypeName{"CHAR", DataType::Char},
                                TypeName{"STRING", DataType::String}, TypeName{"AXIS", DataType::Axis},
                                TypeName{"FRAME", DataType::Frame}};

}  // namespace

bool parse_data_type(std::string_view upper_name, DataType& out) {
  for (const auto& t : kTypeNames)
    if (t.name == upper_name) {
      out = t.type;
      return true;
    }
  return false;
}

std::string_view data_type_name(DataType t) {
  for (const auto& n : kTypeNames)
    if (n.type == t) return n.name;
  return "?";
}

bool is_numeric_type(DataType t) {
  return t == DataType::Int || t == DataType::Real || t == DataType::Bool || t == DataType::Char;
}

double index_from_real(double v) { return std::round(v); }

std::string number_to_text(double v) {
  if (v == std::trunc(v) && std::fabs(v) < 1e15) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.0f", v == 0.0 ? 0.0 : v);
    return buf;
  }
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

}  // namespace drycut::parser
