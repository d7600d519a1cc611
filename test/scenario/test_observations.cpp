#include <gtest/gtest.h>

#include "ari_social_sim/scenario/observations.hpp"
#include "two_humans.hpp"

namespace ari_social_sim::scenario {
namespace {

TEST(PerceivedGroup, MembersAreTheHumansTheirPersonsWereFoundToBe) {
  // Humans 10 at (2, 2) and 11 at (3, 2), seen under a person manager's anonymous ids; a third
  // person, 2 m from both, is nobody the script knows.
  const world::WorldSnapshot world = test::two_humans();
  PersonIdentities identities;
  identities.update(world, {{"anonymous_person_qwert", {3.1, 2.0}, true},
                            {"anonymous_person_asdfg", {1.9, 2.0}, true},
                            {"anonymous_person_zxcvb", {2.5, 4.0}, true}});

  const PerceivedGroup group = perceived_group(
      "g1", {"anonymous_person_qwert", "anonymous_person_zxcvb", "anonymous_person_asdfg"},
      identities);
  EXPECT_EQ(group.group_id, "g1");
  EXPECT_EQ(group.members, (std::vector<AgentRef>{AgentRef::human(11), AgentRef::human(10)}));
  // The suite's own form of id means nothing by itself.
  EXPECT_TRUE(perceived_group("g2", {"human10", "human11"}, identities).members.empty());
}

}  // namespace
}  // namespace ari_social_sim::scenario
