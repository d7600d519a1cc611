#include <gtest/gtest.h>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/world/simulation.hpp"
#include "ari_social_sim/world/world_run_config.hpp"
#include "expect_config_error.hpp"
#include "scene_builders.hpp"

namespace ari_social_sim::world {
namespace {

WorldRunConfig parse(const std::string& text) {
  return WorldRunConfig::from_yaml(core::YamlMap::parse(text, "world_node parameters"));
}

void expect_rejected(const std::string& text, const std::vector<std::string>& fragments) {
  try {
    parse(text);
    FAIL() << "accepted: " << text;
  } catch (const core::ConfigError& e) {
    for (const std::string& fragment : fragments) {
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
  }
}

TEST(WorldRunConfig, DefaultsAreValidAndFieldsAreRead) {
  const WorldRunConfig defaults = parse("{}");
  EXPECT_DOUBLE_EQ(defaults.simulation.step_s, 0.05);
  EXPECT_DOUBLE_EQ(defaults.real_time_factor, 1.0);
  EXPECT_FALSE(defaults.seed.has_value());
  EXPECT_FALSE(parse("{seed: -1}").seed.has_value());  // a launch file's seed:=-1
  const WorldRunConfig config = parse("{step: 0.02, real_time_factor: 0, seed: 4, duration: 40}");
  EXPECT_DOUBLE_EQ(config.simulation.step_s, 0.02);
  EXPECT_DOUBLE_EQ(config.real_time_factor, 0.0);
  EXPECT_EQ(config.seed, std::optional<uint64_t>(4));
  EXPECT_DOUBLE_EQ(config.duration_s, 40.0);
  EXPECT_EQ(defaults.ari_source, AriSource::kInternal);
  EXPECT_EQ(parse("{ari_source: physics}").ari_source, AriSource::kPhysics);
}

TEST(WorldRunConfig, EachBadParameterIsNamed) {
  expect_rejected("{step: -0.1}", {"world_node parameters: step", "(0, 1]", "-0.1"});
  expect_rejected("{step: fast}", {"step", "a number", "fast"});
  expect_rejected("{marker_rate: 100}", {"marker_rate", "(0, 30]"});
  expect_rejected("{real_time_factor: -2}", {"real_time_factor", ">= 0"});
  expect_rejected("{stepp: 0.1}", {"unknown field", "stepp"});
  expect_rejected("{ari_source: gazebo}", {"ari_source", "internal or physics", "gazebo"});
}

TEST(WorldRunConfig, ValidateRefusesABadValueBuiltInCode) {
  WorldRunConfig config;
  EXPECT_NO_THROW(config.validate());
  config.marker_rate_hz = 0.0;
  test::expect_config_error([&] { config.validate(); }, "WorldRunConfig: marker_rate",
                            {"(0, 30]", "got 0"});
}

TEST(SimulationConfig, ValidateRefusesABadValueBuiltInCode) {
  EXPECT_NO_THROW(SimulationConfig{}.validate());
  test::expect_config_error(
      [] {
        SimulationConfig{0.05, 1, 2.0}.validate();
      },
      "SimulationConfig: map_resolution", {"[0.01, 1]", "got 2"});
  // The simulation checks the config it is given before building anything.
  test::expect_config_error(
      [] {
        Simulation(test::square_room(6.0), SimulationConfig{1.5, 1, 0.05});
      },
      "SimulationConfig: step", {"(0, 1]", "got 1.5"});
}

}  // namespace
}  // namespace ari_social_sim::world
