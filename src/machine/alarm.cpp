#include "machine/alarm.hpp"

#include <algorithm>

#include "machine/alarm_catalog.hpp"

namespace drycut {

std::string Alarm::format() const {
  std::string out;
  out.reserve(64 + text.size() + block.size());
  out += where.file.empty() ? std::string("<program>") : where.file;
  out += ':' + std::to_string(where.line) + ':' + std::to_string(where.column) + ": ";
  out += severity == Severity::Warning ? "WARNING " : "ALARM ";
  out += std::to_string(number) + ": " + text;
  if (!block.empty()) out += " | " + block;
  return out;
}

Alarm make_alarm(int number, const std::string& detail, SourceLocation where, std::string block) {
  Alarm a;
  a.number = number;
  const AlarmInfo* info = find_alarm(number);
  a.severity = info ? info->severity : Severity::Alarm;  // Diagnostics::warn makes it a warning
  // 60000..69999: cycle and user alarms raised by the program with SETAL.
  a.text = info ? info->text : (number >= 60000 && number <= 69999) ? "Cycle alarm (SETAL)" : "Unknown alarm";
  if (!detail.empty()) a.text += ": " + detail;
  a.where = std::move(where);
  // A 10 MB line must not produce a 10 MB message: keep the block text readable.
  constexpr size_t kMaxBlockText = 200;
  if (block.size() > kMaxBlockText) {
    block.resize(kMaxBlockText);
    block += "...";
  }
  a.block = std::move(block);
  return a;
}

AlarmError::AlarmError(Alarm alarm) : alarm_(std::move(alarm)), message_(alarm_.format()) {}

bool Diagnostics::has_alarms() const {
  return std::any_of(items_.begin(), items_.end(),
                     [](const Alarm& a) { return a.severity == Severity::Alarm; });
}

size_t Diagnostics::warning_count() const {
  return static_cast<size_t>(std::count_if(items_.begin(), items_.end(), [](const Alarm& a) {
    return a.severity == Severity::Warning;
  }));
}

}  // namespace drycut
