#include <gtest/gtest.h>

#include "ari_social_sim/scenario/group_memory.hpp"
#include "two_humans.hpp"

namespace ari_social_sim::scenario {
namespace {

const std::string kAnna = "anonymous_person_abcde";
const std::string kBert = "anonymous_person_fghij";

// Anna is human 10 and Bert human 11, both seen at their bodies.
PersonIdentities anna_and_bert() {
  PersonIdentities identities;
  identities.update(test::two_humans(), {{kAnna, {2.0, 2.0}, true}, {kBert, {3.0, 2.0}, true}});
  return identities;
}

TEST(GroupMemory, AGroupIsBelievedUntilTheTimeoutAfterItsLastReport) {
  const PersonIdentities identities = anna_and_bert();
  GroupMemory memory(1.0);
  memory.report("grp_b", 2.0, {kAnna, kBert});
  memory.report("grp_a", 2.0, {kBert});
  std::vector<PerceivedGroup> believed = memory.believed_at(2.0, identities);
  // By group id, members mapped to the humans.
  ASSERT_EQ(believed.size(), 2u);
  EXPECT_EQ(believed[0].group_id, "grp_a");
  EXPECT_EQ(believed[1].group_id, "grp_b");
  ASSERT_EQ(believed[1].members.size(), 2u);
  EXPECT_EQ(believed[1].members[0], AgentRef::human(10));
  EXPECT_EQ(believed[1].members[1], AgentRef::human(11));
  // grp_b is reported again at 2.5 s with Anna only; grp_a is not.
  memory.report("grp_b", 2.5, {kAnna});
  believed = memory.believed_at(3.0, identities);
  EXPECT_EQ(believed.size(), 2u);  // 1.0 s after grp_a's report: still believed
  believed = memory.believed_at(3.05, identities);
  ASSERT_EQ(believed.size(), 1u);
  EXPECT_EQ(believed[0].group_id, "grp_b");
  EXPECT_EQ(believed[0].members.size(), 1u);
  EXPECT_TRUE(memory.believed_at(3.55, identities).empty());
  // Forgotten for good: an earlier time does not bring it back.
  EXPECT_TRUE(memory.believed_at(3.0, identities).empty());
}

}  // namespace
}  // namespace ari_social_sim::scenario
