#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "ari_social_sim/engine/episode.hpp"
#include "ari_social_sim/learning/nav_env.hpp"
#include "ari_social_sim/learning/social_score.hpp"
#include "ari_social_sim/navigation/policy.hpp"

namespace ari_social_sim::learning {

/// The learner outside the engine, as a navigation::Policy: when navigation asks it for a
/// command, it keeps the observation it was shown and answers with the action it was given last.
class ExternalPolicy : public navigation::Policy {
 public:
  ExternalPolicy(const NavTaskConfig& task, double step_s);

  const navigation::PolicyObservationConfig& observation() const override { return observation_; }
  double control_rate_hz() const override { return control_rate_hz_; }
  double position_tolerance_m() const override { return arrival_.position_tolerance_m; }
  double heading_tolerance_rad() const override { return arrival_.heading_tolerance_rad; }
  std::array<double, kActions> act(const float* observation) override;

  void set_action(const std::array<float, kActions>& action) { action_ = action; }
  /// True once act() was called since the last take_asked().
  bool take_asked() {
    const bool asked = asked_;
    asked_ = false;
    return asked;
  }
  const std::vector<float>& last_observation() const { return last_; }

 private:
  navigation::PolicyObservationConfig observation_;
  int observation_size_;
  ArrivalRule arrival_;
  double control_rate_hz_;
  std::array<float, kActions> action_{};
  std::vector<float> last_;
  bool asked_{false};
};

/// Task `scenario`: a scenario file played by the batch engine (scenario::Episode, as
/// run_episodes plays it: its scene, script, dialogue and random draws of the seed), with the
/// policy driving ARI's goals in social_mpc_node's place. Whenever the script has a navigation goal
/// pursued, navigation asks the policy at its control rate (one world step); a step() runs the
/// engine until it asks again, or until the script ends. Reward terms as NavEnv's: progress
/// toward the perceived goal of the goal finder, arrival when the goal succeeds, and the social
/// terms on the truth, where everyone counts (the scenario names no one to exempt). Terminated when
/// the script ends (`success` is its outcome), truncated at the time limit.
class ScenarioNavEnv : public Env {
 public:
  explicit ScenarioNavEnv(std::shared_ptr<const NavEnvSetup> setup);
  ~ScenarioNavEnv() override;

  const navigation::PolicyObservation& observation() const override { return observation_; }
  void reset(std::optional<uint64_t> seed, float* observation) override;
  NavStepResult step(const float* action, float* observation) override;
  const NavMetrics& metrics() const override { return metrics_; }
  bool done() const override { return done_; }
  void set_seed_stride(uint64_t stride) override { seeds_.stride = stride; }

 private:
  /// Runs the engine until navigation asks the policy or the script ends; the reward of the
  /// world steps it ran.
  NavStepResult run_until_asked();
  double goal_distance() const;

  std::shared_ptr<const NavEnvSetup> setup_;
  navigation::PolicyObservation observation_;
  int goal_distance_index_{0};  // of the goal's distance in an observation
  ActionBounds bounds_;
  navigation::FootprintModel footprint_;
  std::shared_ptr<ExternalPolicy> policy_;
  engine::EpisodeConfig config_;
  std::unique_ptr<engine::Episode> episode_;
  std::unique_ptr<SocialScore> score_;
  std::array<float, kActionSize> last_action_{};
  std::optional<double> last_distance_m_;
  scenario::NavigationState last_navigation_{scenario::NavigationState::kIdle};
  NavMetrics metrics_;
  bool done_{true};
  bool started_{false};
  SeedSequence seeds_;
};

}  // namespace ari_social_sim::learning
