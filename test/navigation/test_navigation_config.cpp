#include <gtest/gtest.h>

#include "ari_social_sim/navigation/navigation_config.hpp"
#include "ari_social_sim/navigation/navigator.hpp"
#include "expect_config_error.hpp"
#include "navigation_fixtures.hpp"

namespace ari_social_sim::navigation {
namespace {

using world::test::expect_config_error;

NavigationConfig parse(const std::string& text) {
  return NavigationConfig::from_yaml(core::YamlMap::parse(text, "social_mpc.yaml"));
}

TEST(NavigationConfig, ShippedFileSpellsOutTheDefaults) {
  const NavigationConfig defaults;
  const NavigationConfig file =
      NavigationConfig::load_file(std::string(ARI_SOURCE_DIR) + "/config/social_mpc.yaml");
  EXPECT_EQ(file.mpc.horizon_steps, defaults.mpc.horizon_steps);
  EXPECT_DOUBLE_EQ(file.mpc.step_s, defaults.mpc.step_s);
  EXPECT_DOUBLE_EQ(file.mpc.max_linear_mps, defaults.mpc.max_linear_mps);
  EXPECT_EQ(file.mpc.solver, defaults.mpc.solver);
  EXPECT_EQ(file.mpc.max_evaluations, defaults.mpc.max_evaluations);
  EXPECT_DOUBLE_EQ(file.mpc.target_space_fade_m, defaults.mpc.target_space_fade_m);
  EXPECT_DOUBLE_EQ(file.mpc.weights.goal, defaults.mpc.weights.goal);
  EXPECT_DOUBLE_EQ(file.mpc.weights.personal_space, defaults.mpc.weights.personal_space);
  EXPECT_DOUBLE_EQ(file.mpc.weights.reverse, defaults.mpc.weights.reverse);
  EXPECT_DOUBLE_EQ(file.mpc.weights.pan_limit, defaults.mpc.weights.pan_limit);
  EXPECT_DOUBLE_EQ(file.mpc.personal_space.sigma_front_m,
                   defaults.mpc.personal_space.sigma_front_m);
  EXPECT_DOUBLE_EQ(file.mpc.personal_space.person_radius_m,
                   defaults.mpc.personal_space.person_radius_m);
  EXPECT_DOUBLE_EQ(file.goal_finder.approach_distance_m, defaults.goal_finder.approach_distance_m);
  EXPECT_DOUBLE_EQ(file.goal_finder.free_margin_m, defaults.goal_finder.free_margin_m);
  EXPECT_DOUBLE_EQ(file.navigator.rate_hz, defaults.navigator.rate_hz);
  EXPECT_DOUBLE_EQ(file.navigator.patience_halving_s, defaults.navigator.patience_halving_s);
  EXPECT_DOUBLE_EQ(file.navigator.geodesic.group_cost, defaults.navigator.geodesic.group_cost);
  EXPECT_DOUBLE_EQ(file.scene.group_stride_m, defaults.scene.group_stride_m);
}

TEST(NavigationConfig, EmptyMappingGivesTheDefaultsAndKeysOverrideThem) {
  const NavigationConfig empty = parse("{}");
  EXPECT_EQ(empty.mpc.horizon_steps, 20);
  const NavigationConfig tuned = parse(
      "mpc: {solver: mppi, horizon_steps: 30}\nweights: {personal_space: 0}\n"
      "controller: {rate: 20}\ngeodesic: {group_cost: 0}\n");
  EXPECT_EQ(tuned.mpc.solver, SolverKind::kMppi);
  EXPECT_EQ(tuned.mpc.horizon_steps, 30);
  EXPECT_EQ(tuned.mpc.control_count(), 90);
  EXPECT_DOUBLE_EQ(tuned.mpc.weights.personal_space, 0.0);
  EXPECT_DOUBLE_EQ(tuned.navigator.rate_hz, 20.0);
  EXPECT_DOUBLE_EQ(tuned.navigator.geodesic.group_cost, 0.0);
}

TEST(NavigationConfig, EachBadFieldIsNamedWithItsExpectation) {
  expect_config_error([] { parse("mpc: {horizon_steps: 0}"); }, "social_mpc.yaml",
                      {"mpc.horizon_steps", "[5, 100]", "got 0"});
  expect_config_error([] { parse("mpc: {max_linear_speed: 1.5}"); }, "social_mpc.yaml",
                      {"mpc.max_linear_speed", "(0, 1]", "1.5"});
  expect_config_error([] { parse("mpc: {min_linear_speed: -0.5}"); }, "social_mpc.yaml",
                      {"mpc.min_linear_speed", "[-0.2, 0]"});
  expect_config_error([] { parse("mpc: {solver: newton}"); }, "social_mpc.yaml",
                      {"mpc.solver", "lbfgs, slsqp or mppi", "newton"});
  expect_config_error([] { parse("weights: {goal: 0}"); }, "social_mpc.yaml",
                      {"weights.goal", "> 0"});
  expect_config_error([] { parse("weights: {personal_spce: 1}"); }, "social_mpc.yaml",
                      {"weights", "unknown field(s) personal_spce"});
  expect_config_error([] { parse("personal_space: {sigma_side: -1}"); }, "social_mpc.yaml",
                      {"personal_space.sigma_side", "> 0"});
  expect_config_error([] { parse("goal_finder: {approach_distance: 0.1}"); }, "social_mpc.yaml",
                      {"goal_finder.approach_distance", "[0.5, 3]"});
  expect_config_error([] { parse("controller: {rate: 0}"); }, "social_mpc.yaml",
                      {"controller.rate", "[1, 100]"});
  expect_config_error([] { parse("geodesic: {inscribed_radius: 0.5, preferred_clearance: 0.3}"); },
                      "social_mpc.yaml", {"geodesic.preferred_clearance", ">= inscribed_radius"});
  expect_config_error(
      [] { parse("controller: {goal_tolerance: 0.1, join_shortfall_tolerance: 0.12}"); },
      "social_mpc.yaml",
      {"controller.join_shortfall_tolerance", "<= goal_tolerance (0.1)", "0.12"});
  expect_config_error([] { parse("perception_input: {group_timeout: 0}"); }, "social_mpc.yaml",
                      {"perception_input.group_timeout", "> 0"});
  expect_config_error([] { parse("navigation: {}"); }, "social_mpc.yaml",
                      {"top level", "unknown field(s) navigation"});
}

TEST(NavigationConfig, ValidateRefusesABadValueBuiltInCode) {
  NavigationConfig config;
  EXPECT_NO_THROW(config.validate());
  config.mpc.horizon_steps = 2;
  expect_config_error([&] { config.validate(); }, "NavigationConfig: mpc.horizon_steps",
                      {"[5, 100]", "got 2"});
  // The navigator checks the config it is given, before it builds anything from it.
  config = NavigationConfig{};
  config.navigator.geodesic.preferred_clearance_m = 0.1;
  expect_config_error([&] { Navigator(config, test::room_map(6.0)); },
                      "NavigationConfig: geodesic.preferred_clearance",
                      {">= inscribed_radius (0.28)", "got 0.1"});
}

}  // namespace
}  // namespace ari_social_sim::navigation
