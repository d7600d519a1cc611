#include <gtest/gtest.h>

#include "ari_social_sim/scenario/agent_ref.hpp"
#include "expect_config_error.hpp"

namespace ari_social_sim::scenario {
namespace {

TEST(AgentRef, ReadsAriAndHumanIds) {
  const core::YamlMap map = core::YamlMap::parse("{a: ari, b: 11, c: '4294967295'}", "test");
  EXPECT_TRUE(read_agent_ref(map, "a").is_ari());
  EXPECT_EQ(read_agent_ref(map, "b").human_id, 11u);
  EXPECT_EQ(read_agent_ref(map, "c").human_id, 4294967295u);
  EXPECT_EQ(read_agent_ref(map, "b").describe(), "human 11");
  EXPECT_EQ(AgentRef::ari().describe(), "ARI");
}

TEST(AgentRef, RejectsAnythingElseNamingTheField) {
  for (const char* bad : {"robot", "0", "-3", "1.5", "011", "4294967296"}) {
    const core::YamlMap map = core::YamlMap::parse(std::string("{who: '") + bad + "'}", "f.yaml");
    world::test::expect_config_error([&] { read_agent_ref(map, "who"); }, "f.yaml: who",
                                     {"ari or a human id", bad});
  }
}

}  // namespace
}  // namespace ari_social_sim::scenario
