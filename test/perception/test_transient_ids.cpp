#include <gtest/gtest.h>

#include <set>
#include <vector>

#include "ari_social_sim/perception/transient_ids.hpp"

namespace ari_social_sim::perception {
namespace {

// The id's rank among the 26^5 words, its letters read as base-26 digits.
uint32_t rank_of(const std::string& id) {
  uint32_t rank = 0;
  for (char c : id) {
    rank = rank * 26u + static_cast<uint32_t>(c - 'a');
  }
  return rank;
}

TEST(TransientIds, FiveLowercaseLettersNoRepeatIn100000) {
  TransientIds ids(core::Rng(3));
  std::set<std::string> seen;
  for (int i = 0; i < 100000; ++i) {
    const std::string id = ids.next();
    ASSERT_EQ(id.size(), 5u);
    for (char c : id) {
      ASSERT_TRUE(c >= 'a' && c <= 'z') << id;
    }
    ASSERT_TRUE(seen.insert(id).second) << "repeated " << id << " at " << i;
  }
  EXPECT_EQ(ids.issued(), 100000u);
  // The generator's whole state: a counter and four 64-bit round keys, not a set of ids.
  EXPECT_LE(sizeof(TransientIds), 5 * sizeof(uint64_t));
}

TEST(TransientIds, EveryWordOnceBeforeAnyRepeatsThenTheSameCycle) {
  // 26^5 = 11 881 376 ids: each five-letter word exactly once (so no id repeats any of the
  // 11 881 375 before it), then the cycle starts again in the same order, without end.
  TransientIds ids(core::Rng(5));
  std::vector<bool> issued(TransientIds::kIdCount, false);
  std::vector<std::string> first;
  for (uint32_t i = 0; i < TransientIds::kIdCount; ++i) {
    const std::string id = ids.next();
    const uint32_t rank = rank_of(id);
    ASSERT_FALSE(issued[rank]) << id << " issued twice, the second time at " << i;
    issued[rank] = true;
    if (i < 3) {
      first.push_back(id);
    }
  }
  for (const std::string& id : first) {
    EXPECT_EQ(ids.next(), id);
  }
  EXPECT_EQ(ids.issued(), uint64_t{TransientIds::kIdCount} + 3u);
}

TEST(TransientIds, SeededLikeEverythingElse) {
  TransientIds a(core::Rng(7)), b(core::Rng(7)), c(core::Rng(8));
  std::vector<std::string> from_a, from_b, from_c;
  for (int i = 0; i < 10; ++i) {
    from_a.push_back(a.next());
    from_b.push_back(b.next());
    from_c.push_back(c.next());
  }
  EXPECT_EQ(from_a, from_b);
  EXPECT_NE(from_a, from_c);
}

TEST(TransientIds, LettersAreUniform) {
  // 50 000 letters: each of the 26 expected 1923 times, binomial sd 43; within 5 sd.
  TransientIds ids(core::Rng(11));
  std::vector<int> counts(26, 0);
  for (int i = 0; i < 10000; ++i) {
    for (char c : ids.next()) {
      ++counts[c - 'a'];
    }
  }
  for (int count : counts) {
    EXPECT_NEAR(count, 50000.0 / 26.0, 5 * 43.0);
  }
}

TEST(TransientIds, ConsecutiveIdsLookUnrelated) {
  // A counter in disguise would change only the last letters from one id to the next; here each
  // position differs between consecutive ids 25 times in 26 (expected 9 615 of 10 000, sd 19).
  TransientIds ids(core::Rng(13));
  std::vector<int> changed(5, 0);
  std::string previous = ids.next();
  for (int i = 0; i < 10000; ++i) {
    const std::string id = ids.next();
    for (size_t k = 0; k < 5; ++k) {
      changed[k] += id[k] != previous[k] ? 1 : 0;
    }
    previous = id;
  }
  for (int count : changed) {
    EXPECT_NEAR(count, 10000.0 * 25.0 / 26.0, 5 * 19.0);
  }
}

}  // namespace
}  // namespace ari_social_sim::perception
