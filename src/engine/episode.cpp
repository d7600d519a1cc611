#include "ari_social_sim/engine/episode.hpp"

#include "ari_social_sim/core/config_check.hpp"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/perception/group_candidates.hpp"
#include "ari_social_sim/world_speech/small_talk_lines.hpp"

namespace ari_social_sim::engine {

/// The script's commands applied to the cores directly, with the semantics of the services and
/// actions scenario_node calls (README, world_node's services; /tts of dialogue_node).
class Episode::InProcessCommands : public scenario::Commands {
 public:
  InProcessCommands(world::Simulation& world, dialogue::SpokenDialogue& dialogue,
                    InProcessNavigation& navigation)
      : world_(world), dialogue_(dialogue), navigation_(navigation) {}

  void say(const scenario::AgentRef& speaker, const std::string& act,
           const std::string& text) override {
    if (speaker.is_ari()) {
      const std::string refused = dialogue_.request_robot(text, 0.0);
      if (!refused.empty()) {
        throw core::RequestError("/tts: " + refused);
      }
      return;
    }
    world_.say(speaker.human_id, act, text);
  }

  void set_human_goal(model::ObjectId human, const core::Pose2& goal) override {
    world_.set_human_goal(human, goal);
  }

  // As scenario_node: the current goal is cancelled before the next one is sent.
  void navigate(const core::Pose2& goal) override {
    navigation_.cancel();
    navigation_.start(navigation::PoseTarget{goal});
  }

  void approach(const std::string& person_id, bool join_group) override {
    navigation_.cancel();
    if (join_group) {
      navigation_.start(navigation::GroupOfPersonTarget{person_id});
    } else {
      navigation_.start(navigation::PersonTarget{person_id});
    }
  }

  void fail_navigation(const std::string& reason) override { navigation_.fail(reason); }

  void cancel_navigation() override { navigation_.cancel(); }

  void add_human(const world::HumanSpec& spec) override {
    // As /sim/spawn_human, then /sim/set_goal, /sim/set_gaze_targets and /sim/set_reaction.
    world::HumanSpec spawned = spec;
    spawned.goal.reset();
    spawned.gaze.reset();
    spawned.reaction = world::ReactionProfile::kIgnore;
    const model::ObjectId id = world_.add_human(spawned).id();
    if (spec.goal) {
      world_.set_human_goal(id, *spec.goal);
    }
    if (spec.gaze) {
      world_.set_human_gaze(id, *spec.gaze);
    }
    if (spec.reaction != world::ReactionProfile::kIgnore) {
      world_.set_human_reaction(id, spec.reaction);
    }
  }

  void remove_human(model::ObjectId human) override { world_.remove_human(human); }
  void create_group(const world::GroupSpec& spec) override { world_.add_group(spec); }
  void create_walking_group(const world::WalkingGroupSpec& spec) override {
    world_.add_walking_group(spec);
  }
  void add_group_members(model::ObjectId group,
                         const std::vector<model::ObjectId>& members) override {
    world_.add_group_members(group, members);
  }
  void set_group_centre(model::ObjectId group, const Eigen::Vector2d& centre) override {
    world_.set_group_centre(group, centre);
  }
  void set_group_arrangement(model::ObjectId group, model::Arrangement arrangement,
                             std::optional<double> heading_rad) override {
    world_.set_group_arrangement(group, arrangement, heading_rad);
  }
  void leave_group(model::ObjectId agent) override { world_.leave_group(agent); }
  void set_posture(model::ObjectId human, world::Posture posture) override {
    world_.set_human_posture(human, posture);
  }

 private:
  world::Simulation& world_;
  dialogue::SpokenDialogue& dialogue_;
  InProcessNavigation& navigation_;
};

namespace {

perception::PerceptionConfig seeded(perception::PerceptionConfig config, uint64_t seed) {
  config.seed = seed;
  return config;
}

}  // namespace

std::vector<uint32_t> dialogue_cast(const dialogue::DialogueRunConfig& run,
                                    const dialogue::DialogueSetup& setup,
                                    const world::Simulation& simulation,
                                    const scenario::Scenario& scenario) {
  if (!run.humans) {
    return {};
  }
  std::vector<std::pair<uint32_t, std::string>> humans;
  for (const auto& human : simulation.humans()) {
    humans.emplace_back(human->id(), human->spec().role);
  }
  return run.cast(humans, setup.config.users.roles, scenario.scene.path, "dialogue settings");
}

std::unique_ptr<world_speech::WorldSpeechStage> in_process_speech_stage(
    world::Simulation& simulation, std::vector<uint32_t> human_ids) {
  // ARI is part of the scene the simulation was built from: it never comes or goes later.
  const uint32_t robot_id = simulation.ari() != nullptr ? simulation.ari()->id() : 0;
  return std::make_unique<world_speech::WorldSpeechStage>(
      robot_id, std::move(human_ids),
      [&simulation](uint32_t speaker_id, const std::string& act, const std::string& content) {
        try {
          simulation.say(speaker_id, act, content);
        } catch (const core::RequestError&) {
          return false;  // as /sim/say refusing
        }
        return true;
      });
}

EpisodeConfig EpisodeConfig::load(const std::string& config_dir) {
  EpisodeConfig config;
  config.perception = perception::PerceptionConfig::load_file(config_dir + "/perception.yaml");
  config.navigation = navigation::NavigationConfig::load_file(config_dir + "/social_mpc.yaml");
  auto setup = dialogue::DialogueSetup::create(
      dialogue::DialogueConfig::load(config_dir + "/dialogue/simulation.yaml"));
  config.nlu = std::make_shared<const dialogue::RobotNlu>(*setup->nlg, setup->domain,
                                                          setup->corpus_or_null());
  config.dialogue = std::move(setup);
  config.conversation_lines = world_speech::SmallTalkLines::load(config_dir);
  return config;
}

void EpisodeConfig::validate() const {
  core::check_fields(*this, "EpisodeConfig");
}

dialogue::DialogueRunConfig dialogue_run_for(const scenario::Script& script,
                                             dialogue::DialogueRunConfig run) {
  run.mode = dialogue::DialogueMode::kWorld;
  run.humans = script.interfaces().dialogue;
  run.start = dialogue::DialogueStart::kRobotSpeaks;
  run.dialogues = 1;
  return run;
}

Episode::Episode(const scenario::Scenario& scenario, uint64_t seed, const EpisodeConfig& config)
    : seed_(seed),
      config_(core::validated(config)),
      perception_(seeded(config.perception, seed)),
      group_detection_(perception_.config().groups),
      perception_gate_(config.perception_max_rate_hz),
      group_timer_(config.group_detection_rate_hz),
      believed_groups_(config.group_timeout_s),
      dialogue_run_(dialogue_run_for(scenario.script, config.dialogue_run)),
      runner_(scenario, seed, config.dialogue.get(), config.hearing) {
  if (!config.dialogue || !config.nlu) {
    throw core::ConfigError(
        "episode: expected the dialogue settings (EpisodeConfig::load), got none");
  }
  world::Scene scene = scenario.scene;
  scene.seed = seed;
  simulation_ = world::build_simulation(scene, config.simulation);
  simulation_->set_conversation_lines(config.conversation_lines);
  map_ = world::rasterize_static_map(scene.world, config.simulation.map_resolution_m);
  // hri_perception_node sees through /map: walls and furniture block sight and sound.
  perception_.set_sight_map(map_);
  // social_mpc_node plans on the same /map.
  navigation_ =
      std::make_unique<InProcessNavigation>(config.navigation, map_, *simulation_, config.policy);
  dialogue_run_.seed = seed;
  stage_ = in_process_speech_stage(
      *simulation_, dialogue_cast(dialogue_run_, *config.dialogue, *simulation_, scenario));
  dialogue_ = std::make_unique<dialogue::SpokenDialogue>(*config.dialogue, *config.nlu,
                                                         dialogue_run_, *stage_);
  commands_ = std::make_unique<InProcessCommands>(*simulation_, *dialogue_, *navigation_);
  observations_.world = world::WorldSnapshot::of(*simulation_);
}

Episode::~Episode() = default;

void Episode::command_ari(double linear_mps, double angular_rps, double pan_rad) {
  if (simulation_->ari() != nullptr) {
    simulation_->command_ari_twist(linear_mps, angular_rps);
    simulation_->command_ari_head_pan(pan_rad);
  }
}

void Episode::step() {
  if (finished()) {
    return;
  }
  simulation_->step();
  observations_.world = world::WorldSnapshot::of(*simulation_);
  perceive();
  navigate();
  converse();
  runner_.update(observations_, *commands_);
  // Those of the control cycle and those the script's goals caused (a cancel stops the base).
  navigation_commands_ = navigation_->take_commands();
  metrics_.observe(observations_);
}

// As hri_perception_node: the world states its ~max_rate gate (RateGate) takes; group
// detection; and what scenario_node makes of both: who the persons are, and the groups reported
// within its ~group_timeout.
void Episode::perceive() {
  perceived_ = nullptr;
  const double now_s = observations_.world.time_s;
  if (perception_gate_.take(now_s)) {
    perceived_ = &perception_.update(observations_.world);
    latest_frame_ = perceived_;
    navigation_->perceive(*perceived_);
  }
  detect_groups(now_s);
  observations_.transcripts.clear();
  if (perceived_ != nullptr) {
    identify();
    hear();
  }
  observations_.perceived_groups = believed_groups_.believed_at(now_s, identities_);
}

// As group_detection_node on its ~rate timer: GCFF on the persons hri_perception_node tracked in
// its latest frame, each at their body (group_candidates_of); and social_mpc_node receiving the
// groups.
void Episode::detect_groups(double now_s) {
  groups_detected_ = group_timer_.due(now_s) && latest_frame_ != nullptr;
  if (!groups_detected_) {
    return;
  }
  group_detection_.update(perception::group_candidates_of(*latest_frame_), groups_);
  navigation_->receive_groups(groups_, now_s);
  for (const perception::PerceivedGroup& group : groups_) {
    believed_groups_.report(group.group_id, now_s, group.members);
  }
}

// As scenario_node: who each person perception tracks is, from where their body stands.
void Episode::identify() {
  identities_.update(observations_.world, scenario::sightings_of(*perceived_));
  observations_.person_ids = identities_.person_ids();
}

// As scenario_node on /humans/voices/<id>/speech: the final transcripts of this frame.
void Episode::hear() {
  for (const perception::PerceivedVoice& voice : perceived_->voices) {
    for (const perception::SpeechResult& result : voice.speech) {
      if (!result.final_text.empty()) {
        observations_.transcripts.push_back({voice.voice_id, result.final_text, result.confidence});
      }
    }
  }
}

// As social_mpc_node's control timer, on what perception and group detection published last.
void Episode::navigate() {
  navigation_->control();
  observations_.navigation = navigation_->status();
}

// As dialogue_node in world mode on each /sim/world_state, and what scenario_node hears of it on
// /sim/dialogue/utterances and /sim/dialogue/outcome.
void Episode::converse() {
  stage_->follow(observations_.world);
  dialogue_->tick();
  dialogue_events_ = dialogue_->take_events();
  observations_.heard.clear();
  for (const dialogue::UtteranceEvent& event : dialogue_events_.utterances) {
    const dialogue::Utterance& u = dialogue_->live().env().transcript()[event.index];
    if (!u.is_robot()) {
      observations_.heard.push_back(u.heard);
    }
  }
  for (const dialogue::OutcomeEvent& outcome : dialogue_events_.outcomes) {
    observations_.dialogue_end = outcome;
  }
}

}  // namespace ari_social_sim::engine
