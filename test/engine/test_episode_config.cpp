// EpisodeConfig, the batch engine's copy of the live nodes' settings, is checked as a whole by the
// same field rules as the nodes' parameters, whether it comes from the config files or is built in
// code, and an Episode refuses one outside them before it builds anything.
#include <gtest/gtest.h>

#include <string>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/engine/episode.hpp"
#include "refusal_text.hpp"

namespace ari_social_sim::engine {
namespace {

const std::string kSource = ARI_SOURCE_DIR;

const EpisodeConfig& shipped_config() {
  static const EpisodeConfig config = EpisodeConfig::load(kSource + "/config");
  return config;
}

// The message validate() gives for `config`, or "" when it is accepted.
std::string refusal(const EpisodeConfig& config) {
  return world::test::refusal_text<core::ConfigError>([&] { config.validate(); });
}

TEST(EpisodeConfig, TheShippedFilesGiveAValidConfig) {
  EXPECT_EQ(refusal(shipped_config()), "");
  EXPECT_DOUBLE_EQ(shipped_config().perception_max_rate_hz, 30.0);
}

TEST(EpisodeConfig, AValueBuiltInCodeOutsideItsNodesRangeIsRefusedNamingItsPath) {
  EpisodeConfig no_rate = shipped_config();
  no_rate.perception_max_rate_hz = 0.0;
  EXPECT_EQ(refusal(no_rate),
            "EpisodeConfig: perception_max_rate: expected a number (0, 1000], got 0");

  EpisodeConfig long_step = shipped_config();
  long_step.simulation.step_s = 2.0;
  EXPECT_NE(refusal(long_step).find("EpisodeConfig: simulation.step: "), std::string::npos)
      << refusal(long_step);
}

TEST(EpisodeConfig, AnEpisodeRefusesAnInvalidConfigBeforeBuildingTheWorld) {
  const scenario::Scenario scenario =
      scenario::load_scenario_file(kSource + "/scenarios/join_group.yaml");
  EpisodeConfig config = shipped_config();
  config.perception_max_rate_hz = -5.0;
  try {
    Episode episode(scenario, 1, config);
    FAIL() << "an episode started with perception_max_rate -5";
  } catch (const core::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("perception_max_rate"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace ari_social_sim::engine
