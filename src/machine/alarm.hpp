#pragma once
// One alarm type for the whole program (parser, interpreter, planner): a SINUMERIK-style
// number, a severity, the text, where it happened and the block text.
#include <cstddef>
#include <exception>
#include <string>
#include <vector>

#include "machine/source_location.hpp"

namespace drycut {

enum class Severity { Warning, Alarm };

struct Alarm {
  int number = 0;
  Severity severity = Severity::Alarm;
  std::string text;        // catalogue text, optionally followed by ": <detail>"
  SourceLocation where;
  std::string block;       // the block text as written

  // "FILE:LINE:COL: ALARM 12080: <text> | <block>" (WARNING instead of ALARM for warnings).
  std::string format() const;
};

// Builds an alarm whose text is the catalogue text for `number`, plus `detail` when given.
Alarm make_alarm(int number, const std::string& detail, SourceLocation where, std::string block);

// Thrown by any stage when the program cannot go on; carries the alarm.
class AlarmError : public std::exception {
 public:
  explicit AlarmError(Alarm alarm);
  const char* what() const noexcept override { return message_.c_str(); }
  const Alarm& alarm() const { return alarm_; }

 private:
  Alarm alarm_;
  std::string message_;
};

// Usage or I/O problem that is not the program's fault (exit code 2): missing file, bad flag.
class UsageError : public std::exception {
 public:
  explicit UsageError(std::string message) : message_(std::move(message)) {}
  const char* what() const noexcept override { return message_.c_str(); }

 private:
  std::string message_;
};

// Collects warnings (and alarms that do not stop the run) in the order they happen.
class Diagnostics {
 public:
  void report(Alarm alarm) { items_.push_back(std::move(alarm)); }
  void warn(int number, const std::string& detail, SourceLocation where, std::string block) {
    Alarm a = make_alarm(number, detail, std::move(where), std::move(block));
    a.severity = Severity::Warning;
    report(std::move(a));
  }
  const std::vector<Alarm>& items() const { return items_; }
  // Forgets everything reported after the first `count` items.
  void truncate(size_t count) {
    if (count < items_.size()) items_.erase(items_.begin() + static_cast<std::ptrdiff_t>(count), items_.end());
  }
  bool has_alarms() const;
  size_t warning_count() const;

 private:
  std::vector<Alarm> items_;
};

}  // namespace drycut
