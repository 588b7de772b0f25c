#include "report/run_report_writer.hpp"

#include <nlohmann/json.hpp>

#include "report/json_text.hpp"

namespace drycut::report {

using nlohmann::json;

namespace {
constexpr double kMinPerS = 60.0;
constexpr int kFormatVersion = 2;
// Row resolution: far finer than the control's (1 µm positions, ms IPO cycles), coarse enough
// that a row of a 1 M-block program is about 60 bytes.
constexpr int kTimeDecimals = 7;    // 0.1 µs
constexpr int kLengthDecimals = 6;  // 1 nm
constexpr int kFeedDecimals = 3;    // 0.001 mm/min

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

json dip_object(const motion::FeedDip& d) {
  return json{{"file", d.min_source.file_name()},
              {"line", d.min_source.line},
              {"block", d.min_source.text},
              {"first_line", d.source.line},
              {"v_min_mm_min", d.v_min_mm_s * kMinPerS},
              {"programmed_feed_mm_min", d.programmed_feed_mm_s * kMinPerS},
              {"limit", std::string(motion::to_string(d.limit))},
              {"elements", d.element_count},
              {"length_mm", d.length_mm},
              {"main_limit", std::string(motion::to_string(d.main_limit))}};
}

// Block texts come from shop files: replace invalid UTF-8 instead of failing the report.
std::string dump(const json& j, int indent = -1) { return j.dump(indent, ' ', false, json::error_handler_t::replace); }

// A Lines object: {"type": TYPE, ...fields of `fields`}.
std::string typed_line(const char* type, const json& fields) {
  nlohmann::ordered_json line{{"type", type}};  // "type" first, for people reading the stream
  for (const auto& [key, value] : fields.items()) line[key] = value;
  return line.dump(-1, ' ', false, json::error_handler_t::replace) + "\n";
}

}  // namespace

const std::vector<std::string>& block_columns() {
  static const std::vector<std::string> kColumns{"file",         "line",         "label", "time_s", "length_mm",
                                                 "v_max_mm_min", "v_min_mm_min", "limit", "rapid"};
  return kColumns;
}

std::string summary_json(const motion::PlanSummary& summary, int indent) { return dump(summary_object(summary), indent); }
std::string alarm_json(const Alarm& alarm) { return dump(alarm_object(alarm)); }

RunReportWriter::RunReportWriter(std::FILE* out, RunJsonLayout layout, const std::string& program,
                                 const std::string& machine)
    : out_(out), layout_(layout) {
  buffer_.reserve(kFlushBytes + 4096);
  if (layout_ == RunJsonLayout::Lines) {
    buffer_ += typed_line("run", json{{"format", "drycut-run-ndjson"},
                                      {"version", kFormatVersion},
                                      {"program", program},
                                      {"machine", machine}});
    return;
  }
  buffer_ += "{\n\"format\": \"drycut-run\",\n\"version\": " + std::to_string(kFormatVersion) +
             ",\n\"program\": " + dump(json(program)) + ",\n\"machine\": " + dump(json(machine)) +
             ",\n\"block_columns\": " + dump(json(block_columns())) + ",\n\"blocks\": [\n";
}

size_t RunReportWriter::file_index(const BlockRef& source) {
  if (source.file && source.file == last_file_) return last_file_id_;
  const std::string& path = source.file_name();
  auto [it, added] = file_ids_.try_emplace(path, files_.size());
  if (added) {
    files_.push_back(path);
    if (layout_ == RunJsonLayout::Lines) buffer_ += typed_line("file", json{{"id", it->second}, {"path", path}});
  }
  last_file_ = source.file;
  last_file_id_ = it->second;
  return it->second;
}

const std::string& RunReportWriter::escaped_label(const std::string& label) {
  auto it = labels_.find(label);
  if (it != labels_.end()) return it->second;
  if (labels_.size() > 4096) labels_.clear();  // labels carry tool names: bound the cache
  std::string text;
  append_json_string(text, label);
  return labels_.emplace(label, std::move(text)).first->second;
}

void RunReportWriter::on_block(const motion::BlockTiming& t) {
  const size_t file = file_index(t.source);
  const bool lines = layout_ == RunJsonLayout::Lines;
  std::string& b = buffer_;
  if (lines) {
    b += "{\"type\":\"block\",\"file\":";
  } else {
    b += first_row_ ? "[" : ",\n[";
  }
  append_json_integer(b, file);
  b += lines ? ",\"line\":" : ",";
  append_json_integer(b, t.source.line);
  b += lines ? ",\"label\":" : ",";
  b += escaped_label(t.label);
  b += lines ? ",\"time_s\":" : ",";
  append_json_number(b, t.time_s, kTimeDecimals);
  b += lines ? ",\"length_mm\":" : ",";
  append_json_number(b, t.length_mm, kLengthDecimals);
  b += lines ? ",\"v_max_mm_min\":" : ",";
  append_json_number(b, t.v_max_mm_s * kMinPerS, kFeedDecimals);
  b += lines ? ",\"v_min_mm_min\":" : ",";
  append_json_number(b, t.v_min_mm_s * kMinPerS, kFeedDecimals);
  b += lines ? ",\"limit\":\"" : ",\"";
  b += motion::to_string(t.limit);
  b += lines ? "\",\"rapid\":" : "\",";
  b += t.rapid ? "true" : "false";
  if (t.compressed_blocks > 0) {
    // A compressor span: the blocks it replaces and its deviation (two trailing columns).
    b += lines ? ",\"compressed_blocks\":" : ",";
    append_json_integer(b, t.compressed_blocks);
    b += lines ? ",\"deviation_mm\":" : ",";
    append_json_number(b, t.compress_deviation_mm, kLengthDecimals);
  } else if (t.smoothing_deviation_mm >= 0) {
    // A corner-smoothing element: its closest distance to the corner it rounds (one more column).
    b += lines ? ",\"smoothing_deviation_mm\":" : ",";
    append_json_number(b, t.smoothing_deviation_mm, kLengthDecimals);
  }
  b += lines ? "}\n" : "]";
  first_row_ = false;
  if (b.size() >= kFlushBytes) flush();
}

void RunReportWriter::flush() {
  if (!buffer_.empty()) std::fwrite(buffer_.data(), 1, buffer_.size(), out_);
  buffer_.clear();
}

void RunReportWriter::finish(const motion::PlanSummary& summary, const Diagnostics& diagnostics,
                             const RunCompletion& completion, const std::optional<motion::Vec3>& end_position_mm,
                             const RunEventRecorder* events, const std::optional<RunSpan>& span) {
  json dips = json::array();
  for (const auto& d : summary.dips) dips.push_back(dip_object(d));
  json alarms = json::array(), warnings = json::array();
  for (const auto& a : diagnostics.items()) (a.severity == Severity::Warning ? warnings : alarms).push_back(alarm_object(a));
  json summary_with_outcome = summary_object(summary);
  add_outcome(summary_with_outcome, completion, end_position_mm);
  if (events) add_events(summary_with_outcome, *events, span);
  if (layout_ == RunJsonLayout::Lines) {
    for (const auto& d : dips) buffer_ += typed_line("dip", d);
    for (const auto& a : alarms) buffer_ += typed_line("alarm", a);
    for (const auto& w : warnings) buffer_ += typed_line("warning", w);
    buffer_ += typed_line("summary", summary_with_outcome);
  } else {
    buffer_ += "\n],\n\"files\": " + dump(json(files_)) + ",\n\"summary\": " + dump(summary_with_outcome, 2) +
               ",\n\"dips\": " + dump(dips, 2) + ",\n\"alarms\": " + dump(alarms, 2) +
               ",\n\"warnings\": " + dump(warnings, 2) + "\n}\n";
  }
  flush();
  std::fflush(out_);
}

}  // namespace drycut::report
