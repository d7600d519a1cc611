#include <gtest/gtest.h>

#include "../world/expect_config_error.hpp"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/perception/group_detection_run_config.hpp"

namespace ari_social_sim::perception {
namespace {

GroupDetectionRunConfig parse(const std::string& text) {
  return GroupDetectionRunConfig::from_yaml(
      core::YamlMap::parse(text, "/group_detection parameter"));
}

TEST(GroupDetectionRunConfig, NoParametersGiveTheDefaults) {
  const GroupDetectionRunConfig config = parse("{}");
  EXPECT_EQ(config.config, "");
  EXPECT_EQ(config.reference_frame, "map");
  EXPECT_DOUBLE_EQ(config.rate_hz, 20.0);
}

TEST(GroupDetectionRunConfig, ReadsEveryParameter) {
  const GroupDetectionRunConfig config = parse("{config: a.yaml, reference_frame: odom, rate: 15}");
  EXPECT_EQ(config.config, "a.yaml");
  EXPECT_EQ(config.reference_frame, "odom");
  EXPECT_DOUBLE_EQ(config.rate_hz, 15.0);
}

TEST(GroupDetectionRunConfig, BadOrUnknownParametersAreNamed) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"{rate: 0}", "rate: expected a number (0, 1000], got 0"},
      {"{rate: 1001}", "rate: expected a number (0, 1000], got 1001"},
      {"{rate: fast}", "rate: expected a number"},
      {"{reference_frame: ''}",
       "reference_frame: expected a tf frame name without a leading slash or spaces, e.g. map, "
       "got ''"},
      {"{reference_frame: /map}", "reference_frame: expected a tf frame name"},
      {"{reference_frame: 'my map'}", "got 'my map'"},
      {"{max_rate: 30}", "unknown field(s) max_rate"}};
  for (const auto& [text, message] : cases) {
    try {
      parse(text);
      ADD_FAILURE() << "accepted " << text;
    } catch (const core::ConfigError& e) {
      EXPECT_NE(std::string(e.what()).find("/group_detection parameter"), std::string::npos);
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  }
}

TEST(GroupDetectionRunConfig, ValidateRefusesABadValueBuiltInCode) {
  GroupDetectionRunConfig config;
  EXPECT_NO_THROW(config.validate());
  config.reference_frame = "/map";
  world::test::expect_config_error([&] { config.validate(); },
                                   "GroupDetectionRunConfig: reference_frame",
                                   {"expected a tf frame name", "got '/map'"});
}

}  // namespace
}  // namespace ari_social_sim::perception
