#include <gtest/gtest.h>

#include <algorithm>
#include <deque>

#include "motion/ring_buffer.hpp"

namespace drycut::motion {
namespace {

// The planner's window queue against std::deque: pushed at the back, popped at the front, read
// by index, across wrap-arounds and growths (the window can hold thousands of spline segments).
TEST(RingBuffer, BehavesAsADequeAcrossWrapsAndGrowth) {
  RingBuffer<int> ring;
  std::deque<int> reference;
  int next = 0;
  for (int round = 0; round < 40; ++round) {
    const int pushes = (round * 37) % 150 + 1;
    for (int k = 0; k < pushes; ++k) {
      ring.push_back(next);
      reference.push_back(next++);
    }
    const int pops = std::min<int>((round * 53) % 140, static_cast<int>(reference.size()));
    for (int k = 0; k < pops; ++k) {
      ring.pop_front();
      reference.pop_front();
    }
    ASSERT_EQ(ring.size(), reference.size());
    for (size_t i = 0; i < reference.size(); ++i) {
      ASSERT_EQ(ring[i], reference[i]);
    }
    if (!reference.empty()) {
      EXPECT_EQ(ring.back(), reference.back());
    }
  }
  ring.clear();
  EXPECT_TRUE(ring.empty());
  ring.push_back(7);
  EXPECT_EQ(ring[0], 7);
  EXPECT_EQ(ring.size(), 1u);
}

}  // namespace
}  // namespace drycut::motion
