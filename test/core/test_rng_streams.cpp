#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include "ari_social_sim/core/rng_streams.hpp"

namespace ari_social_sim::core {
namespace {

using rng_streams::kAll;

uint64_t last(const RngStreams& streams) {
  return streams.first + (streams.count - 1);
}

TEST(RngStreams, EveryBlockHasANameAComponentAndRoomForItsStreams) {
  for (const RngStreams& streams : kAll) {
    EXPECT_FALSE(streams.name.empty());
    EXPECT_FALSE(streams.component.empty()) << streams.name;
    EXPECT_GE(streams.count, 1u) << streams.name;
    EXPECT_GE(last(streams), streams.first) << streams.name << " wraps past 2^64";
  }
}

TEST(RngStreams, NamesAreUnique) {
  std::set<std::string_view> names;
  for (const RngStreams& streams : kAll) {
    EXPECT_TRUE(names.insert(streams.name).second) << streams.name;
  }
}

// No two components can draw the same numbers from one seed: no value is in two blocks, neither
// a single stream nor any index of a family (a human's gaze by id, ...).
TEST(RngStreams, NoTwoBlocksShareAStream) {
  std::vector<RngStreams> sorted(kAll.begin(), kAll.end());
  std::sort(sorted.begin(), sorted.end(),
            [](const RngStreams& a, const RngStreams& b) { return a.first < b.first; });
  for (size_t i = 1; i < sorted.size(); ++i) {
    EXPECT_GT(sorted[i].first, last(sorted[i - 1]))
        << sorted[i].name << " starts at " << sorted[i].first << ", inside " << sorted[i - 1].name
        << " [" << sorted[i - 1].first << ", " << last(sorted[i - 1]) << "]";
  }
}

// The worked numbers: a human's gaze keeps stream = id (the world's seeded runs and their hashes
// are unchanged), and the perception's first stream sits past every per-id family.
TEST(RngStreams, HumanGazeIsTheIdAndThePerceptionIsAboveEveryId) {
  EXPECT_EQ(rng_streams::kHumanGaze.first + 7, 7u);
  EXPECT_EQ(rng_streams::kHumanReaction.first + 7, (uint64_t{1} << 32) + 7);
  EXPECT_EQ(rng_streams::kPerceptionTransientIds.first, (uint64_t{1} << 40) + 1);
  EXPECT_GT(rng_streams::kPerceptionTransientIds.first, last(rng_streams::kHumanAppearance));
}

TEST(RngStreams, RngForDrawsTheNamedStream) {
  Rng named = rng_for(42, rng_streams::kHumanReaction, 3);
  Rng numbered = Rng::for_stream(42, (uint64_t{1} << 32) + 3);
  EXPECT_EQ(named.next_u64(), numbered.next_u64());
}

TEST(RngStreamsDeathTest, AnIndexPastTheBlockIsABug) {
  EXPECT_DEATH(rng_for(1, rng_streams::kImuNoise, 1), "index < streams.count");
}

}  // namespace
}  // namespace ari_social_sim::core
