#include <gtest/gtest.h>

#include <set>

#include "ari_social_sim/perception/transient_ids.hpp"

namespace ari_social_sim::perception {
namespace {

TEST(TransientIds, FiveLowercaseLettersNeverRepeated) {
  TransientIds ids(core::Rng(3));
  std::set<std::string> seen;
  for (int i = 0; i < 20000; ++i) {
    const std::string id = ids.next();
    ASSERT_EQ(id.size(), 5u);
    for (char c : id) {
      ASSERT_TRUE(c >= 'a' && c <= 'z') << id;
    }
    ASSERT_TRUE(seen.insert(id).second) << "repeated " << id;
  }
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

}  // namespace
}  // namespace ari_social_sim::perception
