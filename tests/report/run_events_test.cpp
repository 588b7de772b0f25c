// RunEventRecorder on hand-made block timings (the clock is the running sum of the block times)
// and the FROM..TO parser.
#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>

#include "report/run_events.hpp"

namespace drycut::report {
namespace {

const FileName kMain = intern_file_name("MAIN.MPF");
const FileName kSubA = intern_file_name("A.SPF");
const FileName kSubB = intern_file_name("B.SPF");

motion::BlockTiming block(FileName file, const char* label, double t, bool after_m0) {
  motion::BlockTiming b;
  b.source.file = file;
  b.label = label;
  b.time_s = t;
  b.after_first_m0 = after_m0;
  return b;
}

TEST(RunEvents, EventsOfACallNestedInACallAndASecondCall) {
  RunEventRecorder r("MAIN.MPF");
  r.on_block(block(kMain, "G4", 0.5, false));   // a dwell before M0: not after_dwell (M0 follows)
  r.on_block(block(kMain, "G1", 1.0, false));   // 0.5 .. 1.5
  r.on_block(block(kMain, "M0", 0.0, false));   // after_m0 = 1.5
  r.on_block(block(kMain, "G4", 2.0, true));    // after_dwell = 3.5
  r.on_block(block(kSubA, "G1", 1.0, true));    // contour_start = 3.5
  r.on_block(block(kSubB, "G1", 0.25, true));   // nested call: still inside the outermost call
  r.on_block(block(kSubA, "G1", 0.25, true));   // contour_end = 5.0
  r.on_block(block(kMain, "G1", 1.0, true));    // the main program goes on: 6.0
  r.on_block(block(kSubA, "G1", 1.0, true));    // a second call does not move contour_end: 7.0
  EXPECT_DOUBLE_EQ(*r.time_of(RunEvent::Start), 0.0);
  EXPECT_DOUBLE_EQ(*r.time_of(RunEvent::AfterM0), 1.5);
  EXPECT_DOUBLE_EQ(*r.time_of(RunEvent::AfterDwell), 3.5);
  EXPECT_DOUBLE_EQ(*r.time_of(RunEvent::ContourStart), 3.5);
  EXPECT_DOUBLE_EQ(*r.time_of(RunEvent::ContourEnd), 5.0);
  EXPECT_DOUBLE_EQ(*r.time_of(RunEvent::End), 7.0);
  EXPECT_DOUBLE_EQ(*r.span_s({RunEvent::AfterDwell, RunEvent::ContourEnd}), 1.5);
}

TEST(RunEvents, WithoutM0TheFirstDwellCountsAndAfterM0HasNoTime) {
  RunEventRecorder r("MAIN.MPF");
  r.on_block(block(kMain, "G1", 1.0, false));
  r.on_block(block(kMain, "G4", 2.0, false));
  r.on_block(block(kMain, "G4", 3.0, false));
  EXPECT_FALSE(r.time_of(RunEvent::AfterM0));
  EXPECT_DOUBLE_EQ(*r.time_of(RunEvent::AfterDwell), 3.0);
  EXPECT_FALSE(r.time_of(RunEvent::ContourStart));
  EXPECT_FALSE(r.time_of(RunEvent::ContourEnd));
  EXPECT_FALSE(r.span_s({RunEvent::AfterM0, RunEvent::End}));
  EXPECT_DOUBLE_EQ(*r.span_s({RunEvent::Start, RunEvent::End}), 6.0);
}

TEST(RunEvents, ParsesSpansAndRefusesUnknownNames) {
  const RunSpan s = parse_span("after_dwell..contour_end");
  EXPECT_EQ(s.from, RunEvent::AfterDwell);
  EXPECT_EQ(s.to, RunEvent::ContourEnd);
  EXPECT_EQ(span_name(s), "after_dwell..contour_end");
  for (RunEvent e : kRunEvents) EXPECT_EQ(parse_event(event_name(e)), e);
  EXPECT_THROW(parse_span("after_m0"), std::invalid_argument);
  EXPECT_THROW(parse_span("after_m0..finish"), std::invalid_argument);
  EXPECT_THROW(parse_span("..end"), std::invalid_argument);
}

}  // namespace
}  // namespace drycut::report
