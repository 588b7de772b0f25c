#include "parser/variable_store.hpp"

#include <cmath>

#include "parser/expression_evaluator.hpp"
#include "parser/line_error.hpp"

namespace drycut::parser {

Variable::Variable(std::string name, DataType type, uint32_t string_length, std::span<const uint32_t> dims)
    : name_(std::move(name)), type_(type), string_length_(string_length) {
  for (size_t k = 0; k < dims.size() && k < 3; ++k) dims_[k] = dims[k];
  rank_ = static_cast<uint8_t>(std::min<size_t>(dims.size(), 3));
  reset();
}

void Variable::reset() {
  if (is_numeric_type(type_))
    numbers_.assign(size(), 0.0);
  else
    texts_.assign(size(), std::string());
}

void Variable::append_state(std::string& out) const {
  if (ref_ || ref_number_) return;  // the target is appended where it lives
  out.append(reinterpret_cast<const char*>(numbers_.data()), numbers_.size() * sizeof(double));
  for (const auto& t : texts_) {
    out += t;
    out += '\0';
  }
}

size_t Variable::element(std::span<const Value> indices, uint32_t column) const {
  if (ref_) {
    if (indices.empty() && rank_ == 0) return ref_offset_;
    return ref_->element(indices, column);
  }
  if (indices.size() != rank_)
    throw LineError(12410, column, name_ + ": " + std::to_string(rank_) + " index(es) expected, " +
                                       std::to_string(indices.size()) + " given");
  size_t flat = 0;
  for (size_t k = 0; k < indices.size(); ++k) {
    const double i = index_from_real(as_number(indices[k], column));
    if (!(i >= 0 && i < dims_[k]))
      throw LineError(k == 0 ? 17020 : 17030, column,
                      name_ + ": index " + number_to_text(i) + " outside 0.." + std::to_string(dims_[k] - 1));
    flat = flat * dims_[k] + static_cast<size_t>(i);
  }
  return flat;
}

Value Variable::get(size_t element) const {
  if (ref_number_) return Value(*ref_number_);
  if (ref_) return ref_->get(element);
  switch (type_) {
    case DataType::String: return Value::of_text(texts_[element]);
    case DataType::Axis: return Value::of_axis(texts_[element]);
    case DataType::Frame: {
      Value f = Value::of_frame();
      f.text = texts_[element];  // the frame's description; empty: the null frame
      return f;
    }
    case DataType::Char: {
      Value c(numbers_[element]);
      c.character = true;
      return c;
    }
    default: return Value(numbers_[element]);
  }
}

void Variable::set(size_t element, const Value& v, uint32_t column) {
  if (ref_number_) {
    *ref_number_ = as_number(v, column);
    return;
  }
  if (ref_) {
    ref_->set(element, v, column);
    return;
  }
  switch (type_) {
    case DataType::String:
      if (v.kind == ValueKind::Frame) throw LineError(12150, column, "a FRAME assigned to STRING " + name_);
      texts_[element] = v.is_number() ? as_text(v) : v.text;
      if (texts_[element].size() > string_length_) texts_[element].resize(string_length_);
      return;
    case DataType::Axis:
      if (v.kind != ValueKind::Axis && !v.is_text()) throw LineError(12150, column, "AXIS " + name_ + " needs an axis name");
      texts_[element] = v.text;
      return;
    case DataType::Frame:
      if (v.kind != ValueKind::Frame) throw LineError(12150, column, "FRAME " + name_ + " needs a frame");
      texts_[element] = v.text;
      return;
    case DataType::Char:
      if (v.is_text() && v.text.size() == 1) {
        numbers_[element] = static_cast<unsigned char>(v.text[0]);
        return;
      }
      numbers_[element] = std::round(as_number(v, column));
      return;
    case DataType::Int: {
      const double x = std::round(as_number(v, column));
      if (std::fabs(x) > 2147483647.0) throw LineError(12160, column, "value outside the INT range for " + name_);
      numbers_[element] = x;
      return;
    }
    case DataType::Bool:  // a STRING is TRUE when not empty (PGA "Type conversion")
      if (v.is_text()) numbers_[element] = v.text.empty() ? 0.0 : 1.0;
      else numbers_[element] = as_number(v, column) != 0.0 ? 1.0 : 0.0;
      return;
    case DataType::Real: numbers_[element] = as_number(v, column); return;
  }
}

Variable* VariableTable::find(std::string_view upper_name) {
  for (auto& v : vars_)
    if (v.name() == upper_name) return &v;
  return nullptr;
}

const Variable* VariableTable::find(std::string_view upper_name) const {
  for (const auto& v : vars_)
    if (v.name() == upper_name) return &v;
  return nullptr;
}

}  // namespace drycut::parser
