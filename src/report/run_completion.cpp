#include "report/run_completion.hpp"

#include <algorithm>
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

void mark_incomplete(std::FILE* out, const RunCompletion& completion) {
  if (completion.complete || !out) return;
  std::fprintf(out, "# INCOMPLETE: %s\n", incomplete_note(completion).c_str());
  std::fflush(out);
}

std::vector<std::string> untimed_cycles(const std::vector<Alarm>& diagnostics) {
  std::vector<std::string> names;
  for (const Alarm& a : diagnostics) {
    if (a.number != 62900 || a.text.find("no time counted") == std::string::npos) continue;
    // "Cycle alarm (SETAL): CYCLE95 (stock removal) not simulated, no time counted": the name
    // is the word after the catalogue text.
    const size_t colon = a.text.find("): ");
    const size_t from = colon == std::string::npos ? 0 : colon + 3;
    const std::string name = a.text.substr(from, a.text.find(' ', from) - from);
    if (!name.empty() && std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  }
  return names;
}

}  // namespace drycut::report
