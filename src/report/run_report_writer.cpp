#include "report/run_report_writer.hpp"

#include <nlohmann/json.hpp>

namespace drycut::report {

using nlohmann::json;

namespace {
constexpr double kMinPerS = 60.0;

json block_json(const motion::BlockTiming& t) {
  return json{{"file", t.source.file_name()},
              {"line", t.source.line},
              {"label", t.label},
              {"time_s", t.time_s},
              {"length_mm", t.length_mm},
              {"v_max_mm_min", t.v_max_mm_s * kMinPerS},
              {"v_min_mm_min", t.v_min_mm_s * kMinPerS},
              {"limit", std::string(motion::to_string(t.limit))},
              {"rapid", t.rapid}};
}

json summary_object(const motion::PlanSummary& s) {
  return json{{"time_s", s.time_s},
              {"time_after_m0_s", s.time_after_m0_s},
              {"path_length_mm", s.path_length_mm},
              {"min_feed_mm_min", s.min_feed_mm_s * kMinPerS},
              {"max_feed_mm_min", s.max_feed_mm_s * kMinPerS},
              {"elements", s.elements},
              {"dips", s.dips.size() + s.dips_not_listed}};
}

// Where the run stopped (null when it went to the end) and where its last motion ended.
void add_outcome(json& summary, const RunCompletion& c, const std::optional<motion::Vec3>& end) {
  summary["complete"] = c.complete;
  summary["stopped_at"] = c.complete ? json() : json{{"file", c.file}, {"line", c.line}, {"alarm", c.alarm_number}};
  summary["end_position_mm"] = end ? json{{"x", end->x()}, {"y", end->y()}, {"z", end->z()}} : json();
}

// `events` {name: seconds or null} and the span asked for (`span` "FROM..TO", `span_s`; null
// without --span or when an event of it has no time).
void add_events(json& summary, const RunEventRecorder& recorder, const std::optional<RunSpan>& span) {
  json events = json::object();
  for (RunEvent e : kRunEvents) {
    const auto t = recorder.time_of(e);
    events[std::string(event_name(e))] = t ? json(*t) : json();
  }
  summary["events"] = events;
  summary["span"] = span ? json(span_name(*span)) : json();
  const auto s = span ? recorder.span_s(*span) : std::nullopt;
  summary["span_s"] = s ? json(*s) : json();
}

json alarm_object(const Alarm& a) {
  return json{{"number", a.number},
              {"severity", a.severity == Severity::Warning ? "warning" : "alarm"},
              {"text", a.text},
              {"file", a.where.file},
              {"line", a.where.line},
              {"column", a.where.column},
              {"block", a.block}};
}

// Block texts come from shop files: replace invalid UTF-8 instead of failing the report.
std::string dump(const json& j, int indent = -1) { return j.dump(indent, ' ', false, json::error_handler_t::replace); }

}  // namespace

std::string summary_json(const motion::PlanSummary& summary, int indent) { return dump(summary_object(summary), indent); }
std::string alarm_json(const Alarm& alarm) { return dump(alarm_object(alarm)); }

RunReportWriter::RunReportWriter(std::FILE* out, const std::string& program, const std::string& machine)
    : out_(out) {
  std::fprintf(out_, "{\n\"program\": %s,\n\"machine\": %s,\n\"blocks\": [\n", dump(json(program)).c_str(),
               dump(json(machine)).c_str());
}

void RunReportWriter::on_block(const motion::BlockTiming& timing) {
  std::fprintf(out_, "%s%s", first_row_ ? "" : ",\n", dump(block_json(timing)).c_str());
  first_row_ = false;
}

void RunReportWriter::finish(const motion::PlanSummary& summary, const Diagnostics& diagnostics,
                             const RunCompletion& completion, const std::optional<motion::Vec3>& end_position_mm,
                             const RunEventRecorder* events, const std::optional<RunSpan>& span) {
  json dips = json::array();
  for (const auto& d : summary.dips)
    dips.push_back({{"file", d.min_source.file_name()},
                    {"line", d.min_source.line},
                    {"block", d.min_source.text},
                    {"first_line", d.source.line},
                    {"v_min_mm_min", d.v_min_mm_s * kMinPerS},
                    {"programmed_feed_mm_min", d.programmed_feed_mm_s * kMinPerS},
                    {"limit", std::string(motion::to_string(d.limit))},
                    {"elements", d.element_count}});
  json alarms = json::array(), warnings = json::array();
  for (const auto& a : diagnostics.items()) (a.severity == Severity::Warning ? warnings : alarms).push_back(alarm_object(a));
  json summary_with_outcome = summary_object(summary);
  add_outcome(summary_with_outcome, completion, end_position_mm);
  if (events) add_events(summary_with_outcome, *events, span);
  std::fprintf(out_, "\n],\n\"summary\": %s,\n\"dips\": %s,\n\"alarms\": %s,\n\"warnings\": %s\n}\n",
               dump(summary_with_outcome, 2).c_str(), dump(dips, 2).c_str(), dump(alarms, 2).c_str(),
               dump(warnings, 2).c_str());
  std::fflush(out_);
}

}  // namespace drycut::report
