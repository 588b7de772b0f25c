#pragma once
// An error found inside one line (lexing, parsing, evaluating). It knows only the column; the
// loader, which knows file, line and block text, turns it into an AlarmError.
#include <cstdint>
#include <exception>
#include <string>

namespace drycut::parser {

class LineError : public std::exception {
 public:
  LineError(int alarm_number, uint32_t column, std::string detail)
      : number_(alarm_number), column_(column), detail_(std::move(detail)) {}
  const char* what() const noexcept override { return detail_.c_str(); }
  int number() const { return number_; }
  uint32_t column() const { return column_; }
  const std::string& detail() const { return detail_; }

 private:
  int number_;
  uint32_t column_;
  std::string detail_;
};

}  // namespace drycut::parser
