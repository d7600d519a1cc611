#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ari_social_sim/model/occupancy_grid.hpp"
#include "ari_social_sim/navigation/goal_controller.hpp"
#include "ari_social_sim/navigation/grid_field.hpp"
#include "ari_social_sim/navigation/navigation_config.hpp"
#include "ari_social_sim/navigation/policy.hpp"
#include "ari_social_sim/navigation/policy_observation.hpp"

namespace ari_social_sim::navigation {

/// A policy driving ARI in SocialMPC's place, as a learned one was trained (learning::NavEnv): each
/// cycle the goal finder places the target on the perceived scene (the last place stands while
/// the target cannot be placed: hidden, out of view), PolicyObservation turns ARI, the scene and
/// the goal into the policy's input, and the policy's action is the command. It arrives by the
/// policy's own arrival rule, and aborts when the goal comes no closer by progress_distance
/// within progress_timeout.
class PolicyController : public GoalController {
 public:
  PolicyController(const NavigationConfig& config, const model::OccupancyGrid& map,
                   std::shared_ptr<Policy> policy);

  void start(const NavigationTarget& target, const PerceivedScene& scene,
             const RobotObservation& robot, double time_s) override;
  void cancel() override;
  NavigatorStep update(double time_s, const RobotObservation& robot,
                       const PerceivedScene& scene) override;

  const std::optional<Goal>& goal() const override { return goal_; }
  const GridField& sdf() const override { return sdf_; }

 private:
  NavigatorStep finish(NavigationState state, const std::string& reason);

  NavigationConfig config_;
  std::shared_ptr<Policy> policy_;
  FootprintModel footprint_;
  GoalFinder goal_finder_;
  GridField sdf_;
  model::OccupancyGrid map_;
  PolicyObservation observation_;
  std::vector<float> input_;
  NavigationState state_{NavigationState::kIdle};
  std::optional<NavigationTarget> target_;
  std::optional<Goal> goal_;
  double best_distance_m_{0.0};
  double best_distance_time_s_{0.0};
};

}  // namespace ari_social_sim::navigation
