// A feed dip is a stretch of cutting elements below the threshold; besides the limit at its
// lowest point it names the limit that bound most of its length (FeedDip::main_limit).
#include <gtest/gtest.h>

#include "motion/feed_dip_collector.hpp"

namespace {

using drycut::BlockRef;
using drycut::motion::FeedDipCollector;
using drycut::motion::Limit;

BlockRef block(uint32_t line) { return BlockRef{nullptr, line, "N" + std::to_string(line)}; }

TEST(FeedDipCollector, AStretchNamesTheLimitOverMostOfItsLength) {
  // F 50 mm/s, threshold 80 % = 40 mm/s. A corner at 4 mm/s (0.1 mm), then 100 blocks of 0.1 mm
  // held at 22 mm/s by the short-block rule: one dip, lowest at the corner, 10.1 mm long, of
  // which 10.0 mm short_block.
  FeedDipCollector dips(0.8, 10);
  dips.add(block(6), block(6), 50.0, 4.0, Limit::Corner, 0.1);
  for (uint32_t k = 0; k < 100; ++k) dips.add(block(7 + k), block(7 + k), 50.0, 22.0, Limit::ShortBlock, 0.1);
  ASSERT_EQ(dips.dips().size(), 1u);
  const auto& d = dips.dips()[0];
  EXPECT_EQ(d.limit, Limit::Corner);
  EXPECT_EQ(d.min_source.line, 6u);
  EXPECT_EQ(d.element_count, 101u);
  EXPECT_NEAR(d.length_mm, 10.1, 1e-9);
  EXPECT_EQ(d.main_limit, Limit::ShortBlock);
}

TEST(FeedDipCollector, EachStretchCountsItsOwnLengths) {
  // The first stretch is mostly short_block; after an element above the threshold a new stretch
  // starts from nothing: a single corner element is its own main limit.
  FeedDipCollector dips(0.8, 10);
  dips.add(block(1), block(1), 50.0, 22.0, Limit::ShortBlock, 5.0);
  dips.add(block(2), block(2), 50.0, 10.0, Limit::Corner, 1.0);
  dips.add(block(3), block(3), 50.0, 50.0, Limit::Feed, 1.0);  // above the threshold: ends it
  dips.add(block(4), block(4), 50.0, 20.0, Limit::Corner, 0.5);
  ASSERT_EQ(dips.dips().size(), 2u);
  EXPECT_EQ(dips.dips()[0].limit, Limit::Corner);
  EXPECT_EQ(dips.dips()[0].main_limit, Limit::ShortBlock);
  EXPECT_NEAR(dips.dips()[0].length_mm, 6.0, 1e-12);
  EXPECT_EQ(dips.dips()[1].main_limit, Limit::Corner);
  EXPECT_NEAR(dips.dips()[1].length_mm, 0.5, 1e-12);
}

}  // namespace
