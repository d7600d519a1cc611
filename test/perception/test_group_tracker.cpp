#include <gtest/gtest.h>

#include "ari_social_sim/perception/group_tracker.hpp"

namespace ari_social_sim::perception {
namespace {

using Ids = std::vector<std::string>;

TEST(GroupTracker, NewGroupsGetFreshIds) {
  GroupTracker tracker;
  EXPECT_EQ(tracker.update({{"a", "b"}, {"c", "d"}}), (Ids{"g1", "g2"}));
  EXPECT_EQ(tracker.update({}), Ids{});
  // Both groups vanished for a frame: they come back with new ids.
  EXPECT_EQ(tracker.update({{"a", "b"}}), (Ids{"g3"}));
}

TEST(GroupTracker, IdsFollowMembershipNotOrder) {
  GroupTracker tracker;
  tracker.update({{"a", "b"}, {"c", "d"}});
  EXPECT_EQ(tracker.update({{"d", "c"}, {"b", "a"}}), (Ids{"g2", "g1"}));
  EXPECT_EQ(tracker.update({{"b", "a"}, {"c", "d"}}), (Ids{"g1", "g2"}));
}

TEST(GroupTracker, GroupKeepsItsIdWhenPeopleJoinOrLeave) {
  GroupTracker tracker;
  tracker.update({{"a", "b"}});
  EXPECT_EQ(tracker.update({{"a", "b", "c"}}), (Ids{"g1"}));
  EXPECT_EQ(tracker.update({{"b", "c"}}), (Ids{"g1"}));
  // Complete turnover one person at a time keeps the id too.
  EXPECT_EQ(tracker.update({{"c", "d"}}), (Ids{"g1"}));
}

TEST(GroupTracker, SplitLeavesTheIdToTheLargerPart) {
  GroupTracker tracker;
  tracker.update({{"a", "b", "c", "d", "e"}});
  // {d,e} shares 2 members, {a,b,c} shares 3: the latter keeps g1.
  EXPECT_EQ(tracker.update({{"d", "e"}, {"a", "b", "c"}}), (Ids{"g2", "g1"}));
}

TEST(GroupTracker, MergeTakesTheIdOfTheLargerContributor) {
  GroupTracker tracker;
  tracker.update({{"a", "b"}, {"c", "d", "e"}});
  EXPECT_EQ(tracker.update({{"a", "b", "c", "d", "e"}}), (Ids{"g2"}));
}

TEST(GroupTracker, EqualOverlapGoesToTheOlderId) {
  GroupTracker tracker;
  tracker.update({{"a", "b"}});
  tracker.update({{"a", "b"}, {"c", "d"}});  // g1 kept, g2 new
  EXPECT_EQ(tracker.update({{"c", "d", "a", "b"}}), (Ids{"g1"}));
}

TEST(GroupTracker, RemembersUnmatchedGroupsForAFewUpdates) {
  GroupTracker tracker(2);
  tracker.update({{"a", "b"}, {"c", "d"}});
  // {a, b} missed for two updates comes back as g1; {c, d} missed for three is forgotten.
  EXPECT_EQ(tracker.update({}), Ids{});
  EXPECT_EQ(tracker.update({}), Ids{});
  EXPECT_EQ(tracker.update({{"a", "b"}}), (Ids{"g1"}));
  EXPECT_EQ(tracker.update({{"c", "d"}}), (Ids{"g3"}));
}

TEST(GroupTracker, ClearForgetsGroupsButNotTheCounter) {
  GroupTracker tracker;
  tracker.update({{"a", "b"}});
  tracker.clear();
  EXPECT_EQ(tracker.update({{"a", "b"}}), (Ids{"g2"}));
}

}  // namespace
}  // namespace ari_social_sim::perception
