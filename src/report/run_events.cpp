#include "report/run_events.hpp"

#include <stdexcept>

namespace drycut::report {

namespace {

constexpr std::string_view kSeparator = "..";

std::string valid_events() {
  std::string out;
  for (RunEvent e : kRunEvents) out += (out.empty() ? "" : ", ") + std::string(event_name(e));
  return out;
}

}  // namespace

std::string_view event_name(RunEvent event) {
  switch (event) {
    case RunEvent::Start: return "start";
    case RunEvent::AfterM0: return "after_m0";
    case RunEvent::AfterDwell: return "after_dwell";
    case RunEvent::ContourStart: return "contour_start";
    case RunEvent::ContourEnd: return "contour_end";
    case RunEvent::End: return "end";
  }
  return "end";
}

std::optional<RunEvent> parse_event(std::string_view name) {
  for (RunEvent e : kRunEvents)
    if (event_name(e) == name) return e;
  return std::nullopt;
}

RunSpan parse_span(std::string_view text) {
  const size_t at = text.find(kSeparator);
  if (at == std::string_view::npos)
    throw std::invalid_argument("span '" + std::string(text) + "' is not FROM..TO (events: " + valid_events() + ")");
  const auto from = parse_event(text.substr(0, at));
  const auto to = parse_event(text.substr(at + kSeparator.size()));
  if (!from || !to)
    throw std::invalid_argument("span '" + std::string(text) + "' names an unknown event (events: " + valid_events() +
                                ")");
  return {*from, *to};
}

std::string span_name(const RunSpan& span) {
  return std::string(event_name(span.from)) + std::string(kSeparator) + std::string(event_name(span.to));
}

RunEventRecorder::RunEventRecorder(std::string main_program_file) : main_file_(std::move(main_program_file)) {}

void RunEventRecorder::on_block(const motion::BlockTiming& timing) {
  const double begin = clock_s_;
  clock_s_ += timing.time_s;
  // The planner reports the M0 itself before the blocks after it (after_first_m0 false on it).
  if (!m0_seen_ && (timing.label == "M0" || timing.after_first_m0)) {
    m0_seen_ = true;
    after_m0_ = timing.label == "M0" ? clock_s_ : begin;
  }
  if (timing.label == "G4") {
    if (!first_dwell_) first_dwell_ = clock_s_;
    if (m0_seen_ && !dwell_after_m0_) dwell_after_m0_ = clock_s_;
  }
  if (contour_over_) return;
  if (timing.source.file != last_file_ || !last_file_) {
    last_file_ = timing.source.file;
    last_in_call_ = timing.source.file_name() != main_file_ && !timing.source.file_name().empty();
  }
  const bool in_call = last_in_call_;
  if (in_call) {
    if (!contour_start_) contour_start_ = begin;
    contour_end_ = clock_s_;
  } else if (contour_start_) {
    contour_over_ = true;  // the main program goes on: the outermost call has returned
  }
}

std::optional<double> RunEventRecorder::time_of(RunEvent event) const {
  switch (event) {
    case RunEvent::Start: return 0.0;
    case RunEvent::AfterM0: return after_m0_;
    case RunEvent::AfterDwell: return m0_seen_ ? dwell_after_m0_ : first_dwell_;
    case RunEvent::ContourStart: return contour_start_;
    case RunEvent::ContourEnd: return contour_end_;
    case RunEvent::End: return clock_s_;
  }
  return std::nullopt;
}

std::optional<double> RunEventRecorder::span_s(const RunSpan& span) const {
  const auto from = time_of(span.from), to = time_of(span.to);
  if (!from || !to) return std::nullopt;
  return *to - *from;
}

}  // namespace drycut::report
