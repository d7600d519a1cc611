#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "ari_social_sim/perception/per_id_store.hpp"

namespace ari_social_sim::perception {
namespace {

TEST(PerIdStore, MadeOnceKeptThroughTheLingerDroppedAfter) {
  std::vector<std::string> made;
  PerIdStore<int> store([&](const std::string& id) {
    made.push_back(id);
    return static_cast<int>(made.size());
  });
  EXPECT_EQ(store.of("abcde", 1.0), 1);
  store.of("abcde", 1.5) += 10;  // the same state, not made again
  EXPECT_EQ(store.of("fghij", 1.5), 2);
  // Linger 1 s: "abcde" last reported at 1.5 s stays up to 2.5 s and goes after.
  store.retire(2.5, 1.0);
  EXPECT_EQ(store.size(), 2u);
  store.of("fghij", 2.6);
  store.retire(2.6, 1.0);
  EXPECT_EQ(store.size(), 1u);
  EXPECT_EQ(store.of("abcde", 2.7), 3);  // back after it went: made afresh
  EXPECT_EQ(made, (std::vector<std::string>{"abcde", "fghij", "abcde"}));
}

TEST(PerIdStore, ZeroLingerKeepsOnlyThisFramesIdsAndTimeGoingBackClears) {
  PerIdStore<int> store([](const std::string&) { return 0; });
  for (int i = 0; i < 1000; ++i) {
    store.of("id" + std::to_string(i), 0.1 * i);
    store.retire(0.1 * i, 0.0);
    ASSERT_EQ(store.size(), 1u);  // 1 000 ids over the run, one at a time in memory
  }
  store.of("late", 200.0);
  store.retire(5.0, 1.0);  // a reset to 5 s: state from 200 s is from another run
  EXPECT_EQ(store.size(), 0u);
}

}  // namespace
}  // namespace ari_social_sim::perception
