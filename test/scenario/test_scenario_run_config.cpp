#include <gtest/gtest.h>

#include "ari_social_sim/scenario/scenario_run_config.hpp"
#include "expect_config_error.hpp"

namespace ari_social_sim::scenario {
namespace {

ScenarioRunConfig read(const std::string& text) {
  return ScenarioRunConfig::from_yaml(core::YamlMap::parse(text, "/scenario_node parameter"));
}

TEST(ScenarioRunConfig, DefaultsAndOverrides) {
  const ScenarioRunConfig defaults = read("{scenario: a.yaml}");
  EXPECT_EQ(defaults.scenario, "a.yaml");
  EXPECT_FALSE(defaults.seed.has_value());
  EXPECT_FALSE(read("{scenario: a.yaml, seed: -1}").seed.has_value());  // a launch file's seed:=-1
  EXPECT_DOUBLE_EQ(defaults.server_timeout_s, 60.0);
  EXPECT_DOUBLE_EQ(defaults.group_timeout_s, 1.0);
  const ScenarioRunConfig set =
      read("{scenario: b.yaml, seed: 12, server_timeout: 5, group_timeout: 0.5}");
  EXPECT_EQ(set.seed, std::optional<uint64_t>(12));
  EXPECT_DOUBLE_EQ(set.server_timeout_s, 5.0);
  EXPECT_DOUBLE_EQ(set.group_timeout_s, 0.5);
  EXPECT_EQ(defaults.hearing, Hearing::kSimulated);
  EXPECT_EQ(read("{scenario: a, hearing: recognised}").hearing, Hearing::kRecognised);
}

TEST(ScenarioRunConfig, WallTimeLimitDefaultsToThreeScriptLimitsPlusTheServerWait) {
  const ScenarioRunConfig defaults = read("{scenario: a.yaml}");
  EXPECT_FALSE(defaults.wall_time_limit_s);
  EXPECT_DOUBLE_EQ(defaults.world_timeout_s, 10.0);
  // A 60 s script: 3 x 60 + 60 s of server_timeout.
  EXPECT_DOUBLE_EQ(defaults.wall_time_limit_for(60.0), 240.0);
  EXPECT_DOUBLE_EQ(read("{scenario: a, wall_time_limit: 30}").wall_time_limit_for(60.0), 30.0);
  EXPECT_DOUBLE_EQ(read("{scenario: a, wall_time_limit: 0}").wall_time_limit_for(60.0), 0.0);
  EXPECT_DOUBLE_EQ(read("{scenario: a, world_timeout: 2.5}").world_timeout_s, 2.5);
}

TEST(ScenarioRunConfig, TimeLimitReplacesTheScriptsOnlyWhenSet) {
  EXPECT_DOUBLE_EQ(read("{scenario: a.yaml}").script_time_limit_for(120.0), 120.0);
  EXPECT_DOUBLE_EQ(read("{scenario: a.yaml, time_limit: 3}").script_time_limit_for(120.0), 3.0);
}

TEST(ScenarioRunConfig, EveryBadParameterIsNamed) {
  const std::string source = "/scenario_node parameter";
  world::test::expect_config_error([] { read("{seed: 1}"); }, source, {"scenario", "required"});
  world::test::expect_config_error([] { read("{scenario: a, seed: -2}"); }, source,
                                   {"seed", "[-1, 2.14748e+09]", "-2"});
  world::test::expect_config_error([] { read("{scenario: a, server_timeout: 0}"); }, source,
                                   {"server_timeout", "> 0", "0"});
  world::test::expect_config_error([] { read("{scenario: a, time_limit: 0}"); }, source,
                                   {"time_limit", "(0, 86400]", "0"});
  world::test::expect_config_error([] { read("{scenario: a, time_limit: abc}"); }, source,
                                   {"time_limit", "abc"});
  world::test::expect_config_error([] { read("{scenario: a, wall_time_limit: -1}"); }, source,
                                   {"wall_time_limit", ">= 0", "-1"});
  world::test::expect_config_error([] { read("{scenario: a, world_timeout: 0}"); }, source,
                                   {"world_timeout", "> 0", "0"});
  world::test::expect_config_error([] { read("{scenario: a, hearing: heard}"); }, source,
                                   {"hearing", "simulated", "recognised", "heard"});
  world::test::expect_config_error([] { read("{scenario: a, group_timout: 1}"); }, source,
                                   {"unknown field(s) group_timout"});
}

TEST(ScenarioRunConfig, ValidateRefusesABadValueBuiltInCode) {
  ScenarioRunConfig config;
  world::test::expect_config_error([&] { config.validate(); }, "ScenarioRunConfig: scenario",
                                   {"required", "got ''"});
  config.scenario = "a.yaml";
  EXPECT_NO_THROW(config.validate());
  config.wall_time_limit_s = -1.0;
  world::test::expect_config_error([&] { config.validate(); }, "ScenarioRunConfig: wall_time_limit",
                                   {">= 0", "got -1"});
}

}  // namespace
}  // namespace ari_social_sim::scenario
