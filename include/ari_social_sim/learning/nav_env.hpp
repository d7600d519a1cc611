#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ari_social_sim/core/rng.hpp"
#include "ari_social_sim/engine/episode.hpp"
#include "ari_social_sim/learning/conversation_task.hpp"
#include "ari_social_sim/learning/nav_task_config.hpp"
#include "ari_social_sim/learning/navigation_episodes.hpp"
#include "ari_social_sim/learning/social_score.hpp"
#include "ari_social_sim/model/occupancy_grid.hpp"
#include "ari_social_sim/navigation/episode_scorer.hpp"
#include "ari_social_sim/navigation/goal_finder.hpp"
#include "ari_social_sim/navigation/grid_field.hpp"
#include "ari_social_sim/navigation/navigation_config.hpp"
#include "ari_social_sim/navigation/policy_observation.hpp"
#include "ari_social_sim/navigation/scene_tracker.hpp"
#include "ari_social_sim/perception/group_perception.hpp"
#include "ari_social_sim/perception/perception_config.hpp"
#include "ari_social_sim/perception/perception_pipeline.hpp"
#include "ari_social_sim/scenario/scenario.hpp"

namespace ari_social_sim::learning {

/// What every environment of a kind shares, read once: the task, the suite's perception and
/// navigation settings (config/perception.yaml, config/social_mpc.yaml: the goal finder, the
/// perceived-scene filter, personal spaces, ARI's footprint) and the shipped worlds.
struct NavEnvSetup {
  NavTaskConfig task;
  perception::PerceptionConfig perception;
  navigation::NavigationConfig navigation;
  EpisodeWorlds worlds;
  /// Task scenario: the scenario file, and the batch engine's settings (run_episodes').
  std::optional<scenario::Scenario> scenario;
  std::optional<engine::EpisodeConfig> episode;
  /// Task join_conversation: the group's words (world_speech::SmallTalkLines, as the engine's).
  std::shared_ptr<const world::ConversationLines> conversation_lines;

  /// From the package's config and worlds directories; `task_file` is a task file
  /// (config/learning/<task>.yaml) and `overrides` YAML text read over it (make()'s options,
  /// named `overrides_source` in errors). Throws core::ConfigError naming the file and field.
  static std::shared_ptr<const NavEnvSetup> load(const std::string& package_dir,
                                                 const std::string& task_file,
                                                 const std::string& overrides,
                                                 const std::string& overrides_source);
};

/// ARI's commands a policy gives, in order: base linear (m/s) and angular (rad/s) velocity, head
/// pan (rad); each clipped to ARI's limits.
inline constexpr int kActionSize = 3;
struct ActionBounds {
  std::array<float, kActionSize> low;
  std::array<float, kActionSize> high;
};
ActionBounds action_bounds();
/// The action's element names, for errors and docs.
inline constexpr const char* kActionNames[kActionSize] = {"linear", "angular", "pan"};
/// join_conversation's action has a 4th element: speak, in [0, 1] (> 0.5: ARI says its next line).
inline constexpr int kConversationActionSize = kActionSize + 1;
inline constexpr const char* kSpeakName = "speak";
/// Elements of a step's action for `task`.
int action_size(NavTask task);
/// Element `index`'s name (kActionNames, then kSpeakName).
const char* action_name(int index);

/// The speak element clipped to [0, 1]. Throws core::RequestError naming it when not finite.
float checked_speak(float speak);

/// `action` (kActionSize values) clipped to `bounds`. Throws core::RequestError naming the
/// element when a value is not finite.
std::array<float, kActionSize> checked_action(const float* action, const ActionBounds& bounds);

/// The seeds a learning environment plays: the one asked for, else the last plus the stride.
struct SeedSequence {
  uint64_t next{0};
  uint64_t stride{1};
  uint64_t take(std::optional<uint64_t> seed) {
    const uint64_t taken = seed.value_or(next);
    next = taken + stride;
    return taken;
  }
};

/// The episode so far, in nav_benchmark's terms (navigation::EpisodeScore) and the task's.
struct NavMetrics {
  bool arrived{false};
  int person_collisions{0};
  int static_collisions{0};
  double personal_space_time_s{0.0};
  double path_length_m{0.0};
  int ospace_intrusions{0};
  double min_person_distance_m{0.0};
  double time_s{0.0};
  double distance_to_goal_m{0.0};  // true goal, straight line
  bool goal_perceived{false};      // the policy's goal comes from perception now
  int gcff_includes_ari{-1};       // join_group, once ended: 1 or 0; else -1
  uint64_t episode_seed{0};
  std::optional<ConversationTaskMetrics> conversation;  // join_conversation only
};

/// What a step returned besides the observation.
struct NavStepResult {
  double reward{0.0};
  bool terminated{false};  // arrived, or a collision with terminate_on_collision
  bool truncated{false};   // the time limit
};

/// A navigation learning environment, as the vector environment and the Python module drive it:
/// NavEnv (nav_benchmark's episodes) or ScenarioNavEnv (a scenario file).
class Env {
 public:
  virtual ~Env() = default;
  virtual const navigation::PolicyObservation& observation() const = 0;
  /// The navigation observation, and after it any part of the task's own.
  virtual int observation_size() const { return observation().size(); }
  virtual std::vector<navigation::ObservationField> observation_fields() const {
    return observation().fields();
  }
  /// Elements of an action: kActionSize, or kConversationActionSize for join_conversation.
  virtual int action_size() const { return kActionSize; }
  /// Starts the episode of `seed`, or of the next seed of the environment's sequence when none
  /// is given (SeedSequence). Writes the first observation.
  virtual void reset(std::optional<uint64_t> seed, float* observation) = 0;
  /// Applies `action` (action_size() values: checked_action, then checked_speak) and writes the
  /// next observation. Throws
  /// core::RequestError naming the element when a value is not finite, and when the episode has
  /// ended or was never reset.
  virtual NavStepResult step(const float* action, float* observation) = 0;
  virtual const NavMetrics& metrics() const = 0;
  virtual bool done() const = 0;
  /// Seeds drawn without an explicit one advance by this (a vector environment's size).
  virtual void set_seed_stride(uint64_t stride) = 0;
};

/// The environment of `setup`'s task.
std::unique_ptr<Env> make_env(std::shared_ptr<const NavEnvSetup> setup);

/// One learning environment: a seeded navigation episode (navigation_episodes.hpp) on the world
/// core, seen through the perception core with its error models, group detection and the
/// perceived-scene filter social_mpc_node uses, with ARI driven by the policy's commands. One
/// step is one world step (0.05 s) with perception and group detection at every step. The
/// observation is navigation::PolicyObservation of the perceived scene, the goal placed by the
/// goal finder on it; until perception has placed the target, the goal is where the task puts
/// it at the start (the instruction), flagged as not perceived. Rewards and the end of an
/// episode are judged on the truth. Seeded: the same seed gives the same episode, bit for bit.
/// Task join_conversation adds ConversationTask: the joined group talks, the action has `speak`
/// and the observation a `conversation` part after the navigation one.
class NavEnv : public Env {
 public:
  explicit NavEnv(std::shared_ptr<const NavEnvSetup> setup);
  ~NavEnv() override;
  NavEnv(const NavEnv&) = delete;
  NavEnv& operator=(const NavEnv&) = delete;

  /// Sim seconds of one step: one world step of the episodes' simulations.
  static double step_s() { return world::SimulationConfig{}.step_s; }
  const navigation::PolicyObservation& observation() const override { return observation_; }
  int observation_size() const override;
  std::vector<navigation::ObservationField> observation_fields() const override;
  int action_size() const override { return learning::action_size(setup_->task.task); }
  const NavEnvSetup& setup() const { return *setup_; }

  void reset(std::optional<uint64_t> seed, float* observation) override;
  /// One world step.
  NavStepResult step(const float* action, float* observation) override;
  const NavMetrics& metrics() const override { return metrics_; }
  bool done() const override { return done_; }
  void set_seed_stride(uint64_t stride) override { seeds_.stride = stride; }

  /// The world, for inspection and rendering.
  const world::Simulation& simulation() const { return *episode_.simulation; }
  const std::optional<navigation::Goal>& true_goal() const { return true_goal_; }

 private:
  void perceive(const world::WorldSnapshot& snapshot);
  void start_conversation();
  void place_goals(bool force);
  void write_observation(float* out) const;
  navigation::RobotObservation robot() const;

  std::shared_ptr<const NavEnvSetup> setup_;
  navigation::FootprintModel footprint_;
  navigation::GoalFinder goal_finder_;
  navigation::PolicyObservation observation_;
  ActionBounds bounds_;

  NavigationEpisode episode_;
  navigation::NavigationTarget target_;
  model::OccupancyGrid map_;
  navigation::GridField sdf_;
  std::unique_ptr<perception::PerceptionPipeline> perception_;
  std::unique_ptr<perception::GroupPerception> groups_;
  std::vector<perception::PerceivedGroup> detected_;
  navigation::SceneTracker tracker_;
  navigation::PerceivedScene scene_;
  std::unique_ptr<SocialScore> score_;
  std::unique_ptr<ConversationTask> conversation_;  // join_conversation only
  core::Rng walk_rng_{0};

  std::optional<navigation::Goal> perceived_goal_;
  std::optional<navigation::Goal> instructed_goal_;
  std::optional<navigation::Goal> true_goal_;
  double next_goal_update_s_{0.0};
  double last_distance_m_{0.0};
  std::array<float, kActionSize> last_action_{};
  bool arrived_before_{false};  // join_conversation goes on after arriving
  NavMetrics metrics_;
  bool done_{true};
  bool started_{false};
  SeedSequence seeds_;
};

}  // namespace ari_social_sim::learning
