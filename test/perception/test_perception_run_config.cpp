#include <gtest/gtest.h>

#include "../world/expect_config_error.hpp"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/perception/perception_run_config.hpp"

namespace ari_social_sim::perception {
namespace {

PerceptionRunConfig parse(const std::string& text) {
  return PerceptionRunConfig::from_yaml(core::YamlMap::parse(text, "/hri_perception parameter"));
}

TEST(PerceptionRunConfig, NoParametersGiveTheDefaults) {
  const PerceptionRunConfig config = parse("{}");
  EXPECT_EQ(config.config, "");
  EXPECT_FALSE(config.seed.has_value());
  EXPECT_FALSE(config.appearance_seed.has_value());
  EXPECT_FALSE(config.errors_enabled.has_value());
  EXPECT_EQ(config.world, "");
  EXPECT_DOUBLE_EQ(config.max_rate_hz, 30.0);
  EXPECT_DOUBLE_EQ(config.id_linger_s, 1.0);
  EXPECT_DOUBLE_EQ(config.marker_rate_hz, 10.0);
  EXPECT_EQ(config.mode, PerceptionRunConfig::Mode::kSim);
  EXPECT_FALSE(config.person_ids.has_value());
}

TEST(PerceptionRunConfig, ModeAndPersonIds) {
  const PerceptionRunConfig config = parse("{mode: detectors, person_ids: random}");
  EXPECT_EQ(config.mode, PerceptionRunConfig::Mode::kDetectors);
  EXPECT_EQ(config.person_ids, std::optional<std::string>("random"));
}

TEST(PerceptionRunConfig, ReadsEveryParameter) {
  const PerceptionRunConfig config = parse(
      "{config: a.yaml, seed: 4, errors_enabled: false, world: w.yaml, max_rate: 15, "
      "id_linger: 0.5, marker_rate: 5}");
  EXPECT_EQ(config.config, "a.yaml");
  EXPECT_EQ(config.seed, std::optional<uint64_t>(4));
  EXPECT_EQ(config.errors_enabled, std::optional<bool>(false));
  EXPECT_EQ(config.world, "w.yaml");
  EXPECT_DOUBLE_EQ(config.max_rate_hz, 15.0);
  EXPECT_DOUBLE_EQ(config.id_linger_s, 0.5);
  EXPECT_DOUBLE_EQ(config.marker_rate_hz, 5.0);
}

// The launch files' `seed:=-1` default ("the config's seed") reaches the node as -1: unset.
TEST(PerceptionRunConfig, MinusOneLeavesTheSeedsUnset) {
  const PerceptionRunConfig config = parse("{seed: -1, appearance_seed: -1}");
  EXPECT_FALSE(config.seed.has_value());
  EXPECT_FALSE(config.appearance_seed.has_value());
  EXPECT_EQ(parse("{seed: 0}").seed, std::optional<uint64_t>(0));
}

TEST(PerceptionRunConfig, BadOrUnknownParametersAreNamed) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"{max_rate: 0}", "max_rate: expected a number (0, 1000], got 0"},
      {"{seed: -2}", "seed: expected an integer [-1, 2.14748e+09], got -2"},
      {"{id_linger: 61}", "id_linger: expected a number [0, 60], got 61"},
      {"{marker_rate: 31}", "marker_rate: expected a number (0, 30], got 31"},
      {"{errors_enabled: 2}", "errors_enabled: expected true or false, got 2"},
      {"{mode: none}", "mode: expected sim or detectors, got 'none'"},
      {"{person_ids: numbered}", "person_ids: expected human or random, got 'numbered'"},
      {"{rate: 30}", "unknown field(s) rate"}};
  for (const auto& [text, message] : cases) {
    try {
      parse(text);
      ADD_FAILURE() << "accepted " << text;
    } catch (const core::ConfigError& e) {
      EXPECT_NE(std::string(e.what()).find("/hri_perception parameter"), std::string::npos);
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  }
}

TEST(PerceptionRunConfig, ValidateRefusesABadValueBuiltInCode) {
  PerceptionRunConfig config;
  EXPECT_NO_THROW(config.validate());
  config.person_ids = "numbered";
  world::test::expect_config_error([&] { config.validate(); }, "PerceptionRunConfig: person_ids",
                                   {"expected human or random, got 'numbered'"});
}

}  // namespace
}  // namespace ari_social_sim::perception
