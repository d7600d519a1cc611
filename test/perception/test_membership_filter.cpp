// MembershipFilter: a regrouping shorter than half the window is ignored, one that lasts is
// followed after a known number of frames, and the first frame passes at once.

#include <gtest/gtest.h>

#include "ari_social_sim/perception/membership_filter.hpp"

namespace ari_social_sim::perception {
namespace {

using Groups = std::vector<std::vector<size_t>>;

const std::vector<std::string> kPeople = {"human10", "human11", "human12", "human20"};
const Groups kWhole = {{0, 1, 2}};  // the three together, human20 alone
const Groups kSplit = {{0, 1}};     // human12 left out
const Groups kTwoGroups = {{0, 1}, {2, 3}};

TEST(MembershipFilter, FirstFramePassesAtOnce) {
  MembershipFilter filter(10);
  EXPECT_EQ(filter.update(kPeople, kTwoGroups), kTwoGroups);
}

TEST(MembershipFilter, WindowOfOnePassesEveryFrameThrough) {
  MembershipFilter filter(1);
  for (const Groups& frame : {kWhole, kSplit, kTwoGroups, kWhole}) {
    EXPECT_EQ(filter.update(kPeople, frame), frame);
  }
}

TEST(MembershipFilter, FlickerBelowHalfTheWindowIsIgnored) {
  MembershipFilter filter(10);
  for (int frame = 0; frame < 10; ++frame) {
    ASSERT_EQ(filter.update(kPeople, kWhole), kWhole);
  }
  // GCFF leaves human12 out every other frame: 5 of each 10 frames at most, never a majority.
  for (int frame = 0; frame < 40; ++frame) {
    EXPECT_EQ(filter.update(kPeople, frame % 2 == 0 ? kSplit : kWhole), kWhole) << frame;
  }
}

TEST(MembershipFilter, LastingSplitIsFollowedOnceItHoldsMostOfTheWindow) {
  MembershipFilter filter(10);
  for (int frame = 0; frame < 10; ++frame) {
    filter.update(kPeople, kWhole);
  }
  // After k split frames the window holds 10 - k together: a tie at k = 5 keeps the group.
  for (int k = 1; k <= 5; ++k) {
    EXPECT_EQ(filter.update(kPeople, kSplit), kWhole) << k;
  }
  EXPECT_EQ(filter.update(kPeople, kSplit), kSplit);
}

TEST(MembershipFilter, OnlyThePeoplePerceivedNowAreGrouped) {
  MembershipFilter filter(10);
  for (int frame = 0; frame < 10; ++frame) {
    filter.update(kPeople, kWhole);
  }
  // human11 unseen: the others are still together, by their own history, in the new indices.
  const std::vector<std::string> without_11 = {"human10", "human12", "human20"};
  EXPECT_EQ(filter.update(without_11, {{0, 1}}), (Groups{{0, 1}}));
  EXPECT_EQ(filter.update(without_11, {}), (Groups{{0, 1}}));
}

TEST(MembershipFilter, PairUnseenForAWindowStartsAfresh) {
  MembershipFilter filter(4);
  for (int frame = 0; frame < 4; ++frame) {
    filter.update(kPeople, kWhole);
  }
  const std::vector<std::string> only_20 = {"human20"};
  for (int frame = 0; frame < 4; ++frame) {
    filter.update(only_20, {});
  }
  // Their history is gone, so this frame's grouping decides at once.
  EXPECT_EQ(filter.update(kPeople, kSplit), kSplit);
}

}  // namespace
}  // namespace ari_social_sim::perception
