#pragma once
// User variables of the NC language (PGA Job Planning, "Flexible NC programming"): typed
// (INT REAL BOOL CHAR STRING[n] AXIS FRAME), scalar or arrays of 1 to 3 dimensions indexed from
// 0, defined by DEF (local: LUD) or in definition files (global: GUD, DEF NCK / DEF CHAN).
// Assignment converts as the control does: REAL -> INT rounds half away from zero, a number
// -> BOOL is "not zero", a one-character string -> CHAR is its code; a string is never
// silently turned into a number (alarm 12150). Indices out of range raise 17020 (first index)
// or 17030 (second and third), a wrong number of indices 12410.
//
// A VAR parameter of a PROC is a reference: the variable aliases its caller's variable, array
// element or R parameter (`ref`), so writes reach the caller at once.
#include <array>
#include <cstdint>
#include <deque>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "parser/value.hpp"

namespace drycut::parser {

class Variable {
 public:
  Variable(std::string name, DataType type, uint32_t string_length, std::span<const uint32_t> dims);

  const std::string& name() const { return name_; }
  DataType type() const { return type_; }
  uint8_t rank() const { return rank_; }
  uint32_t dim(int k) const { return dims_[static_cast<size_t>(k)]; }
  size_t size() const { return static_cast<size_t>(dims_[0]) * dims_[1] * dims_[2]; }
  uint32_t def_line = 0;
  bool standard_definition = false;  // from drycut's own definition files: may be defined again
  // DEF ... SYNR / SYNW / SYNRW: a read / a write of the variable is an implicit preprocessing
  // stop, as a main-run variable's (Job Planning, "Definition of user data": the attributes).
  bool stop_on_read = false;
  bool stop_on_write = false;
  // DEF ... LLI / ULI: the values a write may bring (a numeric variable; +-inf: none given).
  double lower_limit = -std::numeric_limits<double>::infinity();
  double upper_limit = std::numeric_limits<double>::infinity();

  // The element an index list names; throws LineError 12410 / 17020 / 17030.
  size_t element(std::span<const Value> indices, uint32_t column) const;
  Value get(size_t element) const;
  void set(size_t element, const Value& v, uint32_t column);
  // Every element back to its type's zero (a DEF executed again, a new subprogram pass).
  void reset();
  // Appends the values (not a reference's target) as bytes: the loop guard's state.
  void append_state(std::string& out) const;

  // Makes this variable an alias of `target` (element `offset` for a scalar reference), or of a
  // number outside the store (an R parameter).
  void alias(Variable* target, size_t offset) {
    ref_ = target;
    ref_offset_ = offset;
  }
  void alias_number(double* number) { ref_number_ = number; }

 private:
  std::string name_;
  DataType type_;
  uint32_t string_length_;
  uint8_t rank_ = 0;
  std::array<uint32_t, 3> dims_{1, 1, 1};
  std::vector<double> numbers_;      // INT REAL BOOL CHAR
  std::vector<std::string> texts_;   // STRING AXIS
  Variable* ref_ = nullptr;
  size_t ref_offset_ = 0;
  double* ref_number_ = nullptr;
};

// Variables of one scope; addresses stay valid while variables are added (references).
class VariableTable {
 public:
  Variable* find(std::string_view upper_name);
  const Variable* find(std::string_view upper_name) const;
  Variable& add(Variable v) { return vars_.emplace_back(std::move(v)); }
  void clear() { vars_.clear(); }
  void append_state(std::string& out) const {
    for (const auto& v : vars_) v.append_state(out);
  }
  bool empty() const { return vars_.empty(); }

 private:
  std::deque<Variable> vars_;
};

}  // namespace drycut::parser
