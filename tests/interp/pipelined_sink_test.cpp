// The worker-thread hand-over keeps the sequential contract: every element in order, an alarm
// raised downstream stops the stream at its element and carries the producer's mark of it, the
// downstream is still finished, and other exceptions come back as they are.
#include "interp/pipelined_sink.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace drycut::interp {
namespace {

// Records the feed of each element; raises on the element with feed `fail_at` (alarm or other).
class RecordingSink : public ElementSink {
 public:
  double fail_at = -1;
  bool fail_with_runtime_error = false;
  bool fail_in_finish = false;
  std::vector<double> feeds;
  int finished = 0;

  void consume(PathElement&& e) override {
    if (e.feed_mm_s == fail_at) {
      if (fail_with_runtime_error) throw std::runtime_error("disk full");
      throw AlarmError(make_alarm(14800, "test", {}, "N" + std::to_string(static_cast<int>(e.feed_mm_s))));
    }
    feeds.push_back(e.feed_mm_s);
  }
  void finish() override {
    ++finished;
    if (fail_in_finish) throw AlarmError(make_alarm(14800, "follow-up", {}, ""));
  }
};

PathElement element(int i) {
  PathElement e;
  e.feed_mm_s = i;
  return e;
}

using Pipe = PipelinedSink<int>;
constexpr int kMany = static_cast<int>(Pipe::kBatch * (Pipe::kBatchesInFlight + 3)) + 17;

TEST(PipelinedSink, DeliversEveryElementInOrderAndFinishesOnce) {
  RecordingSink down;
  int produced = 0;
  {
    Pipe pipe(down, [&] { return produced; });
    for (; produced < kMany; ++produced) pipe.consume(element(produced));
    pipe.finish();
    EXPECT_FALSE(pipe.failure());
  }
  ASSERT_EQ(down.feeds.size(), static_cast<size_t>(kMany));
  for (int i = 0; i < kMany; ++i) EXPECT_EQ(down.feeds[static_cast<size_t>(i)], i);
  EXPECT_EQ(down.finished, 1);
}

TEST(PipelinedSink, DownstreamAlarmStopsAtItsElementWithItsMark) {
  RecordingSink down;
  down.fail_at = 300;
  int produced = 0;
  bool thrown = false;
  Pipe pipe(down, [&] { return produced * 10; });
  try {
    for (; produced < 100000; ++produced) pipe.consume(element(produced));
  } catch (const AlarmError& e) {
    thrown = true;
    EXPECT_EQ(e.alarm().block, "N300");
  }
  ASSERT_TRUE(thrown) << "the producer is told before it has handed over everything";
  EXPECT_GT(produced, 300);
  // At most the failing batch, the queued ones and the producer's partial batch ahead.
  EXPECT_LE(produced, 300 + static_cast<int>(Pipe::kBatch * (Pipe::kBatchesInFlight + 2)));
  // Winding down: what the producer still sends is dropped without a second throw.
  EXPECT_NO_THROW(pipe.consume(element(1)));
  pipe.finish();
  ASSERT_TRUE(pipe.failure());
  EXPECT_EQ(pipe.failure()->mark, 3000);  // the mark taken as element 300 was handed over
  EXPECT_EQ(pipe.failure()->error.alarm().number, 14800);
  ASSERT_EQ(down.feeds.size(), 300u);
  EXPECT_EQ(down.feeds.back(), 299);
  EXPECT_EQ(down.finished, 1) << "the downstream still flushes what it holds";
}

TEST(PipelinedSink, DrainLetsEarlierElementsRaiseFirst) {
  // A producer alarm after 10 elements: the 6th, still in the partial batch, raises downstream.
  RecordingSink down;
  down.fail_at = 5;
  Pipe pipe(down, [] { return 7; });
  for (int i = 0; i < 10; ++i) pipe.consume(element(i));
  pipe.drain();
  ASSERT_TRUE(pipe.failure());
  EXPECT_EQ(pipe.failure()->mark, 7);
  EXPECT_EQ(down.feeds.size(), 5u);
  EXPECT_NO_THROW(pipe.consume(element(11))) << "drain() has told the producer already";
  pipe.finish();
}

TEST(PipelinedSink, DrainWithoutFailureLeavesTheStreamOpen) {
  RecordingSink down;
  Pipe pipe(down, [] { return 0; });
  for (int i = 0; i < 10; ++i) pipe.consume(element(i));
  pipe.drain();
  EXPECT_FALSE(pipe.failure());
  EXPECT_EQ(down.feeds.size(), 10u);
  for (int i = 10; i < 20; ++i) pipe.consume(element(i));
  pipe.finish();
  EXPECT_EQ(down.feeds.size(), 20u);
}

TEST(PipelinedSink, OtherExceptionsComeBackAsTheyAre) {
  RecordingSink down;
  down.fail_at = 3;
  down.fail_with_runtime_error = true;
  Pipe pipe(down, [] { return 0; });
  for (int i = 0; i < 10; ++i) pipe.consume(element(i));
  EXPECT_THROW(pipe.drain(), std::runtime_error);
  EXPECT_FALSE(pipe.failure());
}

TEST(PipelinedSink, FollowUpAlarmOfTheFlushIsDroppedAfterAFailure) {
  RecordingSink down;
  down.fail_at = 2;
  down.fail_in_finish = true;
  Pipe pipe(down, [] { return 0; });
  for (int i = 0; i < 5; ++i) pipe.consume(element(i));
  EXPECT_NO_THROW(pipe.finish());
  ASSERT_TRUE(pipe.failure());
  EXPECT_EQ(down.finished, 1);
}

TEST(PipelinedSink, AlarmOfTheFlushWithoutFailureIsThrown) {
  RecordingSink down;
  down.fail_in_finish = true;
  Pipe pipe(down, [] { return 0; });
  pipe.consume(element(1));
  EXPECT_THROW(pipe.finish(), AlarmError);
}

}  // namespace
}  // namespace drycut::interp
