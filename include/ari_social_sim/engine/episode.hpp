#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "ari_social_sim/core/sim_timer.hpp"
#include "ari_social_sim/dialogue/dialogue_config.hpp"
#include "ari_social_sim/dialogue/dialogue_run_config.hpp"
#include "ari_social_sim/dialogue/robot_nlu.hpp"
#include "ari_social_sim/dialogue/spoken_dialogue.hpp"
#include "ari_social_sim/engine/in_process_navigation.hpp"
#include "ari_social_sim/model/occupancy_grid.hpp"
#include "ari_social_sim/navigation/navigation_config.hpp"
#include "ari_social_sim/navigation/policy.hpp"
#include "ari_social_sim/perception/group_detection_run_config.hpp"
#include "ari_social_sim/perception/group_perception.hpp"
#include "ari_social_sim/perception/perception_config.hpp"
#include "ari_social_sim/perception/perception_pipeline.hpp"
#include "ari_social_sim/perception/perception_run_config.hpp"
#include "ari_social_sim/perception/rate_gate.hpp"
#include "ari_social_sim/scenario/episode_metrics.hpp"
#include "ari_social_sim/scenario/group_memory.hpp"
#include "ari_social_sim/scenario/person_identities.hpp"
#include "ari_social_sim/scenario/scenario.hpp"
#include "ari_social_sim/scenario/scenario_run_config.hpp"
#include "ari_social_sim/scenario/script_runner.hpp"
#include "ari_social_sim/world/simulation.hpp"
#include "ari_social_sim/world_speech/world_speech_stage.hpp"

namespace ari_social_sim::engine {

/// What the batch tool runs every episode with; the defaults are those of the live nodes, and
/// the parts that every episode shares (the dialogue's domain, models, corpus and NLU) are loaded
/// once.
struct EpisodeConfig {
  world::SimulationConfig simulation;  // step and map resolution (world_node's ~step, ...)
  /// hri_perception_node's config/perception.yaml (group_detection_node reads its `groups:`);
  /// its seed is replaced by the episode's.
  perception::PerceptionConfig perception;
  double perception_max_rate_hz{30.0};   // hri_perception_node's ~max_rate
  double group_detection_rate_hz{20.0};  // group_detection_node's ~rate
  double group_timeout_s{
      scenario::ScenarioRunConfig{}.group_timeout_s};  // scenario_node's ~group_timeout
  /// scenario_node's ~hearing: recognised hears the perception's simulated voices' transcripts.
  scenario::Hearing hearing{scenario::ScenarioRunConfig{}.hearing};
  /// social_mpc_node's parameters (config/social_mpc.yaml).
  navigation::NavigationConfig navigation;
  /// dialogue_node's settings (config/dialogue/simulation.yaml) and parameters in world mode;
  /// the seed is replaced by the episode's, `humans` and `start` follow the script (section 6 of
  /// docs/scenario.md).
  std::shared_ptr<const dialogue::DialogueSetup> dialogue;
  std::shared_ptr<const dialogue::RobotNlu> nlu;
  /// What the world's conversation groups say (world_node's ~config_dir files); null: silent.
  std::shared_ptr<const world::ConversationLines> conversation_lines;
  dialogue::DialogueRunConfig dialogue_run;
  /// A policy that drives ARI's goals in SocialMPC's place (a learner outside the engine,
  /// learning::ScenarioNavEnv); null: the navigation config decides.
  std::shared_ptr<navigation::Policy> policy;

  template <class V>
  void visit(V& v) {
    v.section("simulation", simulation, "world_node's step and map resolution");
    v.section("perception", perception, "hri_perception_node's config/perception.yaml");
    v.field("perception_max_rate", perception_max_rate_hz, "hri_perception_node's ~max_rate",
            perception::PerceptionRunConfig::kMaxRateBounds);
    v.field("group_detection_rate", group_detection_rate_hz, "group_detection_node's ~rate",
            perception::GroupDetectionRunConfig::kRateBounds);
    v.field("group_timeout", group_timeout_s, "scenario_node's ~group_timeout", core::positive());
    v.choice("hearing", hearing, "scenario_node's ~hearing", scenario::kHearings);
    v.section("navigation", navigation, "social_mpc_node's config/social_mpc.yaml");
    v.section("dialogue_run", dialogue_run, "dialogue_node's parameters");
  }

  /// The live nodes' defaults, read from the package's config files under `config_dir`.
  /// Throws core::ConfigError naming the file and field.
  static EpisodeConfig load(const std::string& config_dir);
  /// Throws core::ConfigError naming the first field outside what its node allows, e.g.
  /// `EpisodeConfig: perception_max_rate: expected a number (0, 1000], got 0`.
  void validate() const;
};

/// dialogue_node's parameters for a scenario: simulated humans (who wait for ARI to open the
/// dialogue) when the script converses or waits for the dialogue's end, else ARI's voice only.
dialogue::DialogueRunConfig dialogue_run_for(const scenario::Script& script,
                                             dialogue::DialogueRunConfig run);
/// dialogue_node's cast in world mode: the scene's humans who play the dialogue's roles (none
/// unless `run` has simulated humans). Throws core::ConfigError when a role has nobody.
std::vector<uint32_t> dialogue_cast(const dialogue::DialogueRunConfig& run,
                                    const dialogue::DialogueSetup& setup,
                                    const world::Simulation& simulation,
                                    const scenario::Scenario& scenario);
/// dialogue_node's world stage on the world core in-process: ARI is the simulation's ARI (id 0
/// without one), and each utterance is voiced with Simulation::say, as world_node's /sim/say
/// voices it, a refused request (core::RequestError) counting as refused. Holds a reference to
/// `simulation`, which must outlive the stage.
std::unique_ptr<world_speech::WorldSpeechStage> in_process_speech_stage(
    world::Simulation& simulation, std::vector<uint32_t> human_ids);

/// One run of a scenario with the suite's cores composed in one process, as fast as the machine
/// allows (the batch tool's engine). Each step, in order: the world advances; perception
/// perceives it (at most at its rate), group detection runs on the perceived bodies and the
/// perceived persons are matched with the humans (PersonIdentities); the
/// dialogue follows what the world played and voices what is due; the script runs on what the
/// step produced, as scenario_node does on each /sim/world_state. Seeded: the same scenario,
/// configuration and seed give the same run.
class Episode {
 public:
  /// `seed` replaces the scene's seed, perception's and the dialogue's, and draws the script's
  /// random groups. Throws core::ConfigError when the scene cannot be built or the dialogue's
  /// roles are not in it.
  Episode(const scenario::Scenario& scenario, uint64_t seed, const EpisodeConfig& config);
  ~Episode();
  Episode(const Episode&) = delete;
  Episode& operator=(const Episode&) = delete;

  /// One world step and everything that follows it. Does nothing once the script has ended.
  void step();
  bool finished() const { return runner_.finished(); }

  const world::Simulation& simulation() const { return *simulation_; }
  /// The world after the last step (before the first: the initial state).
  const world::WorldSnapshot& snapshot() const { return observations_.world; }
  const model::OccupancyGrid& map() const { return map_; }
  const scenario::ScriptRunner& runner() const { return runner_; }
  scenario::EpisodeMetrics metrics() const { return metrics_.metrics(); }
  uint64_t seed() const { return seed_; }
  /// What perception reported in the last step; null when it skipped the step (its ~max_rate).
  const perception::PerceptionFrame* perception_frame() const { return perceived_; }
  /// True when group detection ran in the last step (group_detection_node's ~rate timer, on the
  /// latest perception frame).
  bool groups_detected() const { return groups_detected_; }
  /// What group_detection_node reported last (map frame).
  const std::vector<perception::PerceivedGroup>& perceived_groups() const { return groups_; }
  const perception::PerceptionConfig& perception_config() const { return perception_.config(); }
  /// What social_mpc_node commanded in the last step: on its control cycle, and when the script's
  /// goals ended one (a stop).
  const std::vector<navigation::BaseCommand>& navigation_commands() const {
    return navigation_commands_;
  }
  double navigation_rate_hz() const { return config_.navigation.navigator.rate_hz; }
  /// The script's view of navigation's last goal (scenario_node's action client).
  const scenario::NavigationStatus& navigation_status() const { return observations_.navigation; }
  /// Commands ARI's base and head now, as world_node applies /mobile_base_controller/cmd_vel and
  /// /head_controller/command: a learner acting in the policy's place before the next step.
  void command_ari(double linear_mps, double angular_rps, double pan_rad);
  /// What the dialogue reported in the last step (utterances that started, dialogues that ended).
  const dialogue::SpokenDialogueEvents& dialogue_events() const { return dialogue_events_; }
  const dialogue::SpokenDialogue& dialogue() const { return *dialogue_; }

 private:
  class InProcessCommands;

  void perceive();
  void detect_groups(double now_s);
  void identify();
  void hear();
  void navigate();
  void converse();

  uint64_t seed_;
  EpisodeConfig config_;
  std::unique_ptr<world::Simulation> simulation_;
  model::OccupancyGrid map_;
  perception::PerceptionPipeline perception_;
  perception::GroupPerception group_detection_;
  perception::RateGate perception_gate_;
  core::SimTimer group_timer_;
  const perception::PerceptionFrame* perceived_{nullptr};
  // The last frame perception reported (the pipeline keeps it), which group detection runs on.
  const perception::PerceptionFrame* latest_frame_{nullptr};
  bool groups_detected_{false};
  std::vector<perception::PerceivedGroup> groups_;
  scenario::PersonIdentities identities_;
  scenario::GroupMemory believed_groups_;
  std::unique_ptr<InProcessNavigation> navigation_;
  std::vector<navigation::BaseCommand> navigation_commands_;
  dialogue::DialogueRunConfig dialogue_run_;
  std::unique_ptr<world_speech::WorldSpeechStage> stage_;
  std::unique_ptr<dialogue::SpokenDialogue> dialogue_;
  dialogue::SpokenDialogueEvents dialogue_events_;
  std::unique_ptr<InProcessCommands> commands_;
  scenario::ScriptRunner runner_;
  scenario::MetricsRecorder metrics_;
  scenario::Observations observations_;
};

}  // namespace ari_social_sim::engine
