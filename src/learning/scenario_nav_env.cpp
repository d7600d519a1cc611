#include "ari_social_sim/learning/scenario_nav_env.hpp"

#include <cmath>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/model/ari_footprint.hpp"

namespace ari_social_sim::learning {
namespace {

// Where the goal's distance sits in the observation (PolicyObservation's `goal` part).
constexpr int kGoalDistanceIndex = 5;

}  // namespace

ExternalPolicy::ExternalPolicy(const NavTaskConfig& task, double step_s)
    : observation_(task.observation),
      observation_size_(navigation::PolicyObservation(task.observation).size()),
      arrival_(task.arrival),
      control_rate_hz_(1.0 / step_s) {}

std::array<double, navigation::Policy::kActions> ExternalPolicy::act(const float* observation) {
  last_.assign(observation, observation + observation_size_);
  asked_ = true;
  return {action_[0], action_[1], action_[2]};
}

ScenarioNavEnv::ScenarioNavEnv(std::shared_ptr<const NavEnvSetup> setup)
    : setup_(std::move(setup)),
      observation_(setup_->task.observation),
      bounds_(action_bounds()),
      footprint_(navigation::FootprintModel::covering(model::AriFootprint{},
                                                      setup_->navigation.mpc.footprint_circles)) {
  if (!setup_->scenario || !setup_->episode) {
    throw core::ConfigError("learning: task scenario: expected a scenario file, got none");
  }
  for (const navigation::ObservationField& field : observation_.fields()) {
    if (field.name == "goal") {
      goal_distance_index_ = field.offset + kGoalDistanceIndex;
    }
  }
  config_ = *setup_->episode;
  policy_ = std::make_shared<ExternalPolicy>(setup_->task, config_.simulation.step_s);
  config_.policy = policy_;
}

ScenarioNavEnv::~ScenarioNavEnv() = default;

double ScenarioNavEnv::goal_distance() const {
  return policy_->last_observation()[goal_distance_index_];
}

void ScenarioNavEnv::reset(std::optional<uint64_t> seed, float* observation) {
  const uint64_t episode_seed = seeds_.take(seed);
  episode_ = std::make_unique<engine::Episode>(*setup_->scenario, episode_seed, config_);
  score_ = std::make_unique<SocialScore>(footprint_, setup_->navigation.mpc.personal_space,
                                         std::vector<std::string>{}, "",
                                         setup_->navigation.scene.group_stride_m);
  last_action_ = {};
  last_distance_m_.reset();
  last_navigation_ = scenario::NavigationState::kIdle;
  metrics_ = {};
  metrics_.episode_seed = episode_seed;
  policy_->set_action({0.0f, 0.0f, 0.0f});
  policy_->take_asked();
  done_ = false;
  started_ = true;
  const NavStepResult first = run_until_asked();
  done_ = first.terminated || first.truncated;
  const std::vector<float>& last = policy_->last_observation();
  std::fill(observation, observation + observation_.size(), 0.0f);
  std::copy(last.begin(), last.end(), observation);
}

NavStepResult ScenarioNavEnv::step(const float* action, float* observation) {
  if (!started_) {
    throw core::RequestError("learning: step() before reset()");
  }
  if (done_) {
    throw core::RequestError("learning: step() after the episode ended; call reset()");
  }
  const std::array<float, kActionSize> command = checked_action(action, bounds_);
  policy_->set_action(command);
  // The command acts from the coming world step, as NavEnv's does; navigation gives it again
  // when it next asks.
  if (episode_->navigation_status().state == scenario::NavigationState::kActive) {
    episode_->command_ari(command[0], command[1], command[2]);
  }
  NavStepResult result = run_until_asked();
  result.reward += setup_->task.rewards.smoothness * (std::abs(command[0] - last_action_[0]) +
                                                      std::abs(command[1] - last_action_[1]));
  last_action_ = command;
  done_ = result.terminated || result.truncated;
  const std::vector<float>& last = policy_->last_observation();
  std::copy(last.begin(), last.end(), observation);
  return result;
}

NavStepResult ScenarioNavEnv::run_until_asked() {
  const NavTaskConfig& task = setup_->task;
  const RewardWeights& w = task.rewards;
  NavStepResult result;
  for (;;) {
    episode_->step();
    const world::Simulation& sim = episode_->simulation();
    const SocialScore::Step social = score_->add(sim, sim.config().step_s, w);
    result.reward += social.reward;

    const scenario::NavigationState navigation = episode_->navigation_status().state;
    if (navigation == scenario::NavigationState::kSucceeded &&
        last_navigation_ != scenario::NavigationState::kSucceeded) {
      result.reward += w.arrival;
    }
    last_navigation_ = navigation;
    const bool asked = policy_->take_asked();
    if (asked) {
      const double distance = goal_distance();
      if (last_distance_m_) {
        result.reward += w.progress * (*last_distance_m_ - distance);
      }
      last_distance_m_ = distance;
      metrics_.distance_to_goal_m = distance;
      metrics_.goal_perceived = true;
    }
    if (navigation != scenario::NavigationState::kActive) {
      last_distance_m_.reset();  // the next goal's distances start afresh
    }

    score_->fill(metrics_, sim.time_s());
    const bool collided = task.terminate_on_collision && social.collisions > 0;
    if (episode_->finished() || collided) {
      metrics_.arrived = episode_->finished() && episode_->runner().outcome()->success;
      result.terminated = true;
      return result;
    }
    if (sim.time_s() >= task.time_limit_s - 1e-9) {
      result.truncated = true;
      return result;
    }
    if (asked) {
      return result;
    }
  }
}

}  // namespace ari_social_sim::learning
