#include "report/run_completion.hpp"

#include <filesystem>

namespace drycut::report {

RunCompletion run_completion(const std::vector<Alarm>& diagnostics, bool ended_in_alarm) {
  RunCompletion c;
  for (const Alarm& a : diagnostics) {
    if (a.severity != Severity::Alarm) continue;
    c.complete = false;
    c.alarm_number = a.number;
    c.file = a.where.file;
    c.line = a.where.line;
    return c;
  }
  c.complete = !ended_in_alarm;
  return c;
}

std::string incomplete_note(const RunCompletion& c) {
  std::string where = std::filesystem::path(c.file).filename().string();
  if (where.empty()) where = "<program>";
  std::string alarm = c.alarm_number ? "alarm " + std::to_string(c.alarm_number) : std::string("an alarm");
  return "stopped by " + alarm + " at " + where + ":" + std::to_string(c.line) +
         "; the figures cover the blocks before it";
}

}  // namespace drycut::report
