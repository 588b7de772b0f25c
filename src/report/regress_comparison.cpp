#include "report/regress_comparison.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>

#include "machine/alarm.hpp"

namespace drycut::report {

namespace {

std::string number_text(double value, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, value);
  return buf;
}

Tolerance parse_tolerance(const std::string& key, std::string value) {
  Tolerance t;
  const bool percent = !value.empty() && value.back() == '%';
  if (percent) value.pop_back();
  double v = -1;
  const auto r = std::from_chars(value.data(), value.data() + value.size(), v);
  if (value.empty() || r.ec != std::errc() || r.ptr != value.data() + value.size() || !(v >= 0) || !std::isfinite(v))
    throw UsageError("--tolerance " + key + "=" + value + (percent ? "%" : "") +
                     ": the value must be a number >= 0, with % for a share of the baseline");
  (percent ? t.relative : t.absolute) = percent ? v / 100.0 : v;
  return t;
}

// One numeric figure: a change when the tolerance does not allow the difference.
void compare_value(std::vector<RegressChange>& out, const std::string& program, const char* what, const char* unit,
                   double base, double now, const Tolerance& tolerance, int decimals) {
  if (tolerance.allows(base, now)) return;
  std::string note;
  if (base != 0) {
    const double percent = (now - base) / std::abs(base) * 100.0;
    note = (percent >= 0 ? "+" : "") + number_text(percent, 1) + " %, ";
  }
  note += "tolerance " + tolerance.text();
  out.push_back({program, what, number_text(base, decimals) + unit, number_text(now, decimals) + unit, note});
}

// Alarms or warnings: every key only in the baseline is gone, every key only now is new.
void compare_diagnostics(std::vector<RegressChange>& out, const std::string& program, const char* what,
                         const std::vector<DiagnosticKey>& base, const std::vector<DiagnosticKey>& now) {
  const std::set<DiagnosticKey> before(base.begin(), base.end()), after(now.begin(), now.end());
  for (const auto& k : before)
    if (!after.count(k)) out.push_back({program, what, k.text(), "-", "gone"});
  for (const auto& k : after)
    if (!before.count(k)) out.push_back({program, what, "-", k.text(), "new"});
}

void compare_program(std::vector<RegressChange>& out, const ProgramFigures& b, const ProgramFigures& n,
                     const RegressTolerances& t) {
  const std::string& p = n.program;
  if (b.error != n.error) out.push_back({p, "error", b.error.empty() ? "-" : b.error, n.error.empty() ? "-" : n.error, ""});
  compare_diagnostics(out, p, "alarm", b.alarms, n.alarms);  // the cause before its effects
  if (b.complete != n.complete)
    out.push_back({p, "complete", b.complete ? "yes" : "no", n.complete ? "yes" : "no",
                   n.complete ? "runs to the end now" : "stopped by an alarm"});
  compare_value(out, p, "time", " s", b.time_s, n.time_s, t.time, 2);
  compare_value(out, p, "time after M0", " s", b.time_after_m0_s, n.time_after_m0_s, t.time, 2);
  compare_value(out, p, "lowest feed", " mm/min", b.min_feed_mm_min, n.min_feed_mm_min, t.feed, 1);
  compare_value(out, p, "path length", " mm", b.path_length_mm, n.path_length_mm, t.length, 3);
  compare_value(out, p, "feed dips", "", static_cast<double>(b.dips), static_cast<double>(n.dips), t.dips, 0);
  compare_diagnostics(out, p, "warning", b.warnings, n.warnings);
}

}  // namespace

bool Tolerance::allows(double baseline, double now) const {
  if (!std::isfinite(baseline) || !std::isfinite(now)) return baseline == now;
  // A little slack for the rounding of the stored baseline (0.1 ms, 0.001 mm/min, 0.1 µm).
  return std::abs(now - baseline) <= relative * std::abs(baseline) + absolute + 1e-3;
}

std::string Tolerance::text() const {
  if (relative > 0 || absolute == 0) {
    std::ostringstream s;
    s << relative * 100.0 << " %";
    return s.str();
  }
  std::ostringstream s;
  s << absolute;
  return s.str();
}

RegressTolerances parse_tolerances(const std::string& spec) {
  RegressTolerances t;
  const std::map<std::string, Tolerance*> fields{
      {"time", &t.time}, {"feed", &t.feed}, {"length", &t.length}, {"dips", &t.dips}};
  std::istringstream items(spec);
  std::string item;
  while (std::getline(items, item, ',')) {
    if (item.empty()) continue;
    const auto eq = item.find('=');
    const std::string key = item.substr(0, eq);
    const auto field = fields.find(key);
    if (eq == std::string::npos || field == fields.end())
      throw UsageError("--tolerance " + item + ": expected KEY=VALUE with KEY one of time, feed, length, dips");
    *field->second = parse_tolerance(key, item.substr(eq + 1));
  }
  return t;
}

std::string RegressChange::message() const {
  std::string m = what + " " + baseline + " -> " + now;
  if (!note.empty()) m += " (" + note + ")";
  return m;
}

std::vector<RegressChange> compare_with_baseline(const Baseline& baseline, const std::vector<ProgramFigures>& now,
                                                 const RegressTolerances& tolerances) {
  std::map<std::string, const ProgramFigures*> before, after;
  for (const auto& f : baseline.programs) before[f.program] = &f;
  for (const auto& f : now) after[f.program] = &f;
  std::vector<RegressChange> changes;
  for (const auto& [program, figures] : after) {
    const auto b = before.find(program);
    if (b == before.end())
      changes.push_back({program, "new program", "-", "run", "not in the baseline"});
    else
      compare_program(changes, *b->second, *figures, tolerances);
  }
  for (const auto& [program, figures] : before)
    if (!after.count(program)) changes.push_back({program, "missing program", "in baseline", "-", "not found or not run"});
  std::stable_sort(changes.begin(), changes.end(),
                   [](const RegressChange& a, const RegressChange& b) { return a.program < b.program; });
  return changes;
}

std::string change_table(const std::vector<RegressChange>& changes) {
  const std::vector<std::string> head{"program", "what", "baseline", "now", "note"};
  std::vector<size_t> width(head.size());
  const auto cells = [](const RegressChange& c) { return std::vector<std::string>{c.program, c.what, c.baseline, c.now, c.note}; };
  for (size_t i = 0; i < head.size(); ++i) width[i] = head[i].size();
  for (const auto& c : changes) {
    const auto row = cells(c);
    for (size_t i = 0; i < row.size(); ++i) width[i] = std::max(width[i], row[i].size());
  }
  std::string out;
  const auto line = [&](const std::vector<std::string>& row) {
    for (size_t i = 0; i < row.size(); ++i) {
      out += row[i];
      if (i + 1 < row.size()) out += std::string(width[i] - row[i].size() + 2, ' ');
    }
    while (!out.empty() && out.back() == ' ') out.pop_back();
    out += '\n';
  };
  line(head);
  std::vector<std::string> rule;
  for (size_t w : width) rule.push_back(std::string(w, '-'));
  line(rule);
  for (const auto& c : changes) line(cells(c));
  return out;
}

}  // namespace drycut::report
