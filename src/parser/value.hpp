#pragma once
// A value of the NC language while an expression is evaluated: a number (INT, REAL, BOOL and
// CHAR are numbers; CHAR holds its character code) or a text (STRING; AXIS holds the axis name;
// FRAME carries the text of the frame function that made it, "CTRANS(X,10)", computed by the
// interpreter where a frame variable is written; see docs/language.md). Conversions follow the PGA "data types" table:
// REAL -> INT rounds half away from zero, any number -> BOOL is "not zero", a number becomes a
// text only through `<<` or SPRINT.
#include <cstdint>
#include <string>
#include <string_view>

namespace drycut::parser {

enum class DataType : uint8_t { Int, Real, Bool, Char, String, Axis, Frame };

enum class ValueKind : uint8_t { Number, Text, Axis, Frame };

struct Value {
  ValueKind kind = ValueKind::Number;
  double number = 0.0;
  std::string text;  // Text: the string; Axis: the axis name (upper case)
  // A number read from a CHAR: its code in arithmetic, the character where it becomes a STRING
  // (`<<`, an assignment to STRING; Job Planning, "Possible type conversions").
  bool character = false;

  Value() = default;
  explicit Value(double v) : number(v) {}
  static Value of_text(std::string s) {
    Value v;
    v.kind = ValueKind::Text;
    v.text = std::move(s);
    return v;
  }
  static Value of_axis(std::string name) {
    Value v;
    v.kind = ValueKind::Axis;
    v.text = std::move(name);
    return v;
  }
  static Value of_frame() {
    Value v;
    v.kind = ValueKind::Frame;
    return v;
  }
  bool is_number() const { return kind == ValueKind::Number; }
  bool is_text() const { return kind == ValueKind::Text; }
};

// Data type names as written in DEF: "INT" -> Int; false for an unknown name.
bool parse_data_type(std::string_view upper_name, DataType& out);
std::string_view data_type_name(DataType t);
bool is_numeric_type(DataType t);

// An index (of an array, an R parameter, a string's character, G[n], M[n] ...) is an INT: a REAL
// written there is converted as on assignment, rounded half away from zero, so `A[R1*3-1]` with
// R1*3-1 = 2.0000000000000004 is A[2] (docs/language-rules.md "Variables").
double index_from_real(double v);

// How `<<` writes a number: integers without a decimal point, other values with up to 10
// significant digits and no trailing zeros ("1.5", "-0.001", "3").
std::string number_to_text(double v);

}  // namespace drycut::parser
