#include <gtest/gtest.h>

#include <fstream>
#include <memory>
#include <string>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/navigation/mlp_policy.hpp"
#include "ari_social_sim/navigation/navigation_errors.hpp"
#include "ari_social_sim/navigation/policy_controller.hpp"
#include "navigation_fixtures.hpp"

namespace ari_social_sim::navigation {
namespace {

// A policy over a small observation (no people, a 1-cell patch: 3 + 6 + 4 + 1 = 14 values) whose
// one linear layer drives forward by the goal's x and turns by its y, head still.
std::string policy_text(const std::string& weight_count_override = "") {
  std::string weight = "[";
  for (int o = 0; o < 3; ++o) {
    for (int i = 0; i < 14; ++i) {
      const bool forward = o == 0 && i == 4;  // goal x
      const bool turn = o == 1 && i == 5;     // goal y
      weight += std::string(o + i > 0 ? ", " : "") + (forward || turn ? "1" : "0");
    }
  }
  weight += weight_count_override.empty() ? "]" : ", " + weight_count_override + "]";
  std::string zeros = "[0", ones = "[1";
  for (int i = 1; i < 14; ++i) {
    zeros += ", 0";
    ones += ", 1";
  }
  zeros += "]";
  ones += "]";
  return "format: ari_social_sim/mlp_policy/1\ntask: go_to_pose\ncontrol_rate: 20\n"
         "arrival: {position_tolerance: 0.25, heading_tolerance: 0.35}\n"
         "observation: {nearest_people: 0, patch_cells: 1, patch_resolution: 0.25, "
         "people_range: 8.0}\n"
         "observation_mean: " +
         zeros + "\nobservation_std: " + ones +
         "\nobservation_clip: 10.0\naction_low: [-0.2, -2.094, -1.309]\n"
         "action_high: [1.0, 2.094, 1.309]\n"
         "layers:\n  - {activation: none, inputs: 14, outputs: 3, bias: [0, 0, 0], weight: " +
         weight + "}\n";
}

std::string write(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

TEST(MlpPolicy, MapsTheNetworksOutputOntoAriLimits) {
  MlpPolicy policy = MlpPolicy::load_file(write("policy_ok.yaml", policy_text()));
  EXPECT_EQ(policy.task(), "go_to_pose");
  EXPECT_DOUBLE_EQ(policy.control_rate_hz(), 20.0);
  float observation[14] = {};
  observation[4] = 0.5f;   // goal 0.5 m ahead: output 0.5 -> linear 0.7 m/s
  observation[5] = -3.0f;  // far to the right: clipped to -1 -> the angular limit
  const auto action = policy.act(observation);
  EXPECT_NEAR(action[0], -0.2 + 0.75 * 1.2, 1e-6);
  EXPECT_NEAR(action[1], -2.094, 1e-6);
  EXPECT_NEAR(action[2], 0.0, 1e-6);
}

TEST(MlpPolicy, RefusesFilesThatDoNotChainByName) {
  std::string text = policy_text();
  const auto refusal = [](const std::string& name, const std::string& body) {
    try {
      MlpPolicy::load_file(write(name, body));
    } catch (const core::ConfigError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(refusal("policy_weights.yaml", policy_text("7"))
                .find("layers[0].weight: expected 42 numbers, got 43"),
            std::string::npos);
  std::string other_format = text;
  other_format.replace(other_format.find("mlp_policy/1"), 12, "mlp_policy/9");
  EXPECT_NE(refusal("policy_format.yaml", other_format)
                .find("format: expected ari_social_sim/mlp_policy/1"),
            std::string::npos);
  std::string bad_std = text;
  bad_std.replace(bad_std.find("observation_std: [1"), 19, "observation_std: [0");
  EXPECT_NE(refusal("policy_std.yaml", bad_std).find("observation_std"), std::string::npos);
  std::string wide = text;
  wide.replace(wide.find("inputs: 14"), 10, "inputs: 15");
  EXPECT_NE(refusal("policy_inputs.yaml", wide).find("layers[0].inputs: expected 14"),
            std::string::npos);
}

TEST(PolicyController, DrivesToThePoseAndArrivesByThePolicysRule) {
  auto policy =
      std::make_shared<MlpPolicy>(MlpPolicy::load_file(write("policy_drive.yaml", policy_text())));
  PolicyController controller(NavigationConfig{}, test::room_map(8.0), policy);
  RobotObservation robot;
  robot.pose = test::pose(2.0, 4.0, 0.0);
  EXPECT_THROW(controller.start(PersonTarget{"human9"}, PerceivedScene{}, robot, 0.0),
               UnknownTarget);
  controller.start(PoseTarget{test::pose(5.0, 4.0, 0.0)}, PerceivedScene{}, robot, 0.0);
  // A unicycle following the commands at 20 Hz reaches the goal.
  NavigatorStep step;
  double t = 0.0;
  for (; t < 20.0; t += 0.05) {
    step = controller.update(t, robot, PerceivedScene{});
    if (step.state != NavigationState::kActive) {
      break;
    }
    EXPECT_EQ(step.phase, "policy");
    robot.pose.theta += step.command.angular_rps * 0.05;
    robot.pose.position += step.command.linear_mps * 0.05 * robot.pose.heading();
  }
  EXPECT_EQ(step.state, NavigationState::kSucceeded);
  EXPECT_LE((robot.pose.position - Eigen::Vector2d(5.0, 4.0)).norm(), 0.25);
  EXPECT_LT(t, 6.0);
}

}  // namespace
}  // namespace ari_social_sim::navigation
