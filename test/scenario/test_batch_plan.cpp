#include <gtest/gtest.h>

#include <set>

#include "ari_social_sim/scenario/batch_plan.hpp"
#include "expect_config_error.hpp"

namespace ari_social_sim::scenario {
namespace {

TEST(BatchPlan, ShardsCoverEveryEpisodeOnce) {
  std::multiset<uint64_t> seen;
  for (unsigned k = 1; k <= 3; ++k) {
    BatchPlan plan{10, 100, k, 3};
    for (uint64_t i : plan.episode_indices()) {
      seen.insert(i);
    }
  }
  EXPECT_EQ(seen, (std::multiset<uint64_t>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9}));
  const BatchPlan second{10, 100, 2, 3};
  EXPECT_EQ(second.episode_indices(), (std::vector<uint64_t>{1, 4, 7}));
  EXPECT_EQ(second.seed_of(7), 107u);
  // More shards than episodes: the last shards have nothing to do.
  EXPECT_TRUE((BatchPlan{2, 1, 3, 4}).episode_indices().empty());
}

TEST(BatchPlan, ParsesShardsAndNamesBadOnes) {
  BatchPlan plan;
  parse_shard("3/8", "command line", plan);
  EXPECT_EQ(plan.shard_index, 3u);
  EXPECT_EQ(plan.shard_count, 8u);
  for (const char* bad : {"0/4", "5/4", "3", "a/4", "3/", "/4", "-1/4", "1/4/2"}) {
    world::test::expect_config_error([&] { parse_shard(bad, "command line", plan); },
                                     "command line: --shard", {"1 <= K <= N", bad});
  }
}

TEST(BatchPlan, SeedsMustStayBelowTwoToThe31) {
  world::test::expect_config_error(
      [] {
        (BatchPlan{10, 2147483640u, 1, 1}).validate("command line");
      },
      "command line: --seed", {"2147483640..2147483649", "below 2^31"});
  world::test::expect_config_error(
      [] {
        (BatchPlan{0, 1, 1, 1}).validate("command line");
      },
      "command line: --episodes", {"at least 1"});
  EXPECT_NO_THROW((BatchPlan{8, 2147483640u, 1, 1}).validate("command line"));
}

}  // namespace
}  // namespace ari_social_sim::scenario
