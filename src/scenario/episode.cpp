#include "ari_social_sim/scenario/episode.hpp"

#include "ari_social_sim/core/error.hpp"

namespace ari_social_sim::scenario {

/// The script's commands applied to the cores directly, with the semantics of the services and
/// actions scenario_node calls (README, world_node's services).
class Episode::InProcessCommands : public Commands {
 public:
  InProcessCommands(world::Simulation& world, std::vector<SpokenByAri>& ari_speech)
      : world_(world), ari_speech_(ari_speech) {}

  void say(const AgentRef& speaker, const std::string& act, const std::string& text) override {
    if (speaker.is_ari()) {
      throw core::RequestError("ARI's text-to-speech is not composed in batch runs yet");
    }
    world_.speech_of(speaker.human_id).say(act, text, world_.time_s());
  }

  void set_human_goal(world::ObjectId human, const core::Pose2& goal) override {
    world_.set_human_goal(human, goal);
  }

  void navigate(const core::Pose2&) override { no_navigation(); }
  void approach(world::ObjectId, bool) override { no_navigation(); }
  void cancel_navigation() override { no_navigation(); }

  void add_human(const world::HumanSpec& spec) override {
    // As /sim/spawn_human, then /sim/set_goal and /sim/set_gaze_targets.
    world::HumanSpec spawned = spec;
    spawned.goal.reset();
    spawned.gaze.reset();
    world_.add_human(spawned);
    if (spec.goal) {
      set_human_goal(spec.id, *spec.goal);
    }
    if (spec.gaze) {
      world_.find_human(spec.id)->set_gaze_model(*spec.gaze);
    }
  }

  void remove_human(world::ObjectId human) override { world_.remove_human(human); }
  void create_group(const world::GroupSpec& spec) override { world_.add_group(spec); }
  void add_group_members(world::ObjectId group,
                         const std::vector<world::ObjectId>& members) override {
    world_.add_group_members(group, members);
  }
  void set_group_centre(world::ObjectId group, const Eigen::Vector2d& centre) override {
    world::GroupNavigation* found = world_.find_group(group);
    if (found == nullptr) {
      throw core::RequestError("no group with id " + std::to_string(group));
    }
    found->set_centre(centre);
  }

 private:
  [[noreturn]] static void no_navigation() {
    throw core::RequestError("ARI's navigation is not composed in batch runs yet");
  }

  world::Simulation& world_;
  std::vector<SpokenByAri>& ari_speech_;
};

namespace {

perception::PerceptionConfig seeded(perception::PerceptionConfig config, uint64_t seed) {
  config.seed = static_cast<unsigned>(seed);
  return config;
}

}  // namespace

EpisodeConfig EpisodeConfig::load(const std::string& config_dir) {
  EpisodeConfig config;
  config.perception = perception::PerceptionConfig::load_file(config_dir + "/perception.yaml");
  return config;
}

Episode::Episode(const Scenario& scenario, uint64_t seed, const EpisodeConfig& config)
    : scenario_(scenario),
      seed_(seed),
      config_(config),
      perception_(seeded(config.perception, seed)),
      runner_(scenario, seed) {
  world::Scene scene = scenario.scene;
  scene.seed = seed;
  simulation_ = world::build_simulation(scene, config.simulation);
  map_ = world::rasterize_static_map(scene.world, config.simulation.map_resolution_m);
  // hri_perception_node sees through /map: walls and furniture block sight and sound.
  perception_.set_sight_map(map_);
  commands_ = std::make_unique<InProcessCommands>(*simulation_, ari_speech_);
  observations_.world = world::WorldSnapshot::of(*simulation_);
}

Episode::~Episode() = default;

void Episode::step() {
  if (finished()) {
    return;
  }
  ari_speech_.clear();
  simulation_->step();
  observations_.world = world::WorldSnapshot::of(*simulation_);
  perceive();
  runner_.update(observations_, *commands_);
  metrics_.observe(observations_);
}

// As hri_perception_node: every world state unless closer than its maximum rate to the last one.
void Episode::perceive() {
  perceived_ = nullptr;
  const double time_s = observations_.world.time_s;
  const double period_s = 1.0 / config_.perception_max_rate_hz;
  if (last_perceived_s_ && time_s - *last_perceived_s_ < 0.999 * period_s) {
    return;
  }
  last_perceived_s_ = time_s;
  perceived_ = &perception_.update(observations_.world);
  observations_.perceived_groups.clear();
  for (const perception::PerceivedGroup& group : perceived_->groups) {
    observations_.perceived_groups.push_back(perceived_group(group.group_id, group.members));
  }
}

}  // namespace ari_social_sim::scenario
