#include "ari_social_sim/world/scene.hpp"

#include <filesystem>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/model/world_file.hpp"
#include "ari_social_sim/world/request_check.hpp"

namespace ari_social_sim::world {
namespace {

core::Pose2 read_pose(const core::YamlMap& map) {
  core::Pose2 pose;
  pose.position = map.required<Eigen::Vector2d>("position");
  pose.theta = map.optional<double>("orientation", 0.0);
  return pose;
}

// Turns a core::RequestError from a spec's own validation into a ConfigError naming the entry.
template <class Spec>
void validate_entry(const Spec& spec, const core::YamlMap& entry) {
  try {
    spec.validate();
  } catch (const core::RequestError& e) {
    throw core::ConfigError(entry.where() + ": " + e.what());
  }
}

GazeModel read_gaze(const core::YamlMap& map) {
  GazeModel gaze;
  gaze.mean_duration_s = map.required<double>("mean_duration", core::positive());
  const std::vector<core::YamlMap> targets = map.list("targets", true);
  if (targets.size() > kMaxGazeTargets) {
    map.fail("targets", "at most " + std::to_string(kMaxGazeTargets) + " targets",
             std::to_string(targets.size()));
  }
  for (const core::YamlMap& target : targets) {
    gaze.targets.push_back({target.required<unsigned>("id", core::positive()),
                            target.required<double>("probability", core::between(0.0, 1.0))});
    target.finish();
  }
  if (map.has("directions")) {
    const core::YamlMap d = map.map("directions");
    GazeDirections directions;
    const std::string distribution = d.required<std::string>("distribution");
    if (distribution == "uniform") {
      directions.distribution = GazeDirections::Distribution::kUniform;
      directions.low_rad = d.required<double>("low");
      directions.high_rad = d.required<double>("high");
    } else if (distribution == "normal") {
      directions.distribution = GazeDirections::Distribution::kNormal;
      directions.mean_rad = d.required<double>("mean");
      directions.stddev_rad = d.required<double>("stddev", core::non_negative());
    } else {
      d.fail("distribution", "uniform or normal", "'" + distribution + "'");
    }
    d.finish();
    gaze.directions = directions;
  }
  if (gaze.targets.empty() == !gaze.directions.has_value()) {
    map.fail("targets", "either a list of targets or directions (exactly one of them)",
             gaze.targets.empty() ? "neither" : "both");
  }
  double total = 0.0;
  for (const GazeTarget& t : gaze.targets) {
    total += t.probability;
  }
  if (!gaze.targets.empty() && std::abs(total - 1.0) > 1e-6) {
    map.fail("targets", "probabilities summing to 1", "a sum of " + std::to_string(total));
  }
  map.finish();
  return gaze;
}

}  // namespace

HumanSpec parse_human(const core::YamlMap& entry) {
  HumanSpec spec;
  spec.id = entry.required<unsigned>("id", core::positive());
  spec.name = entry.optional<std::string>("name", "");
  spec.role = entry.optional<std::string>("role", "");
  spec.pose.position = entry.required<Eigen::Vector2d>("position");
  spec.pose.theta = entry.optional<double>("orientation", 0.0);
  spec.age_years = entry.optional<double>("age", spec.age_years, core::between(0.0, 130.0));
  const std::string gender = entry.optional<std::string>("gender", "non-identified");
  if (const auto parsed = model::parse_gender(gender)) {
    spec.gender = *parsed;
  } else {
    entry.fail("gender", model::kGenderChoices, "'" + gender + "'");
  }
  spec.mask = entry.optional<bool>("mask", false);
  const std::string emotion = entry.optional<std::string>("emotion", "neutral");
  if (const auto parsed = model::parse_emotion(emotion)) {
    spec.emotion = *parsed;
  } else {
    entry.fail("emotion", model::kEmotionChoices, "'" + emotion + "'");
  }
  spec.words_per_minute =
      entry.optional<double>("words_per_minute", spec.words_per_minute, core::positive());
  if (entry.has("motion")) {
    const core::YamlMap m = entry.map("motion");
    HumanMotionParams& p = spec.motion;
    p.walking_speed_mps =
        m.optional<double>("walking_speed", p.walking_speed_mps, core::positive());
    p.max_speed_mps = m.optional<double>("max_speed", p.max_speed_mps, core::positive());
    p.turn_gain_per_s = m.optional<double>("turn_gain", p.turn_gain_per_s, core::positive());
    p.goal_distance_m = m.optional<double>("goal_distance", p.goal_distance_m, core::positive());
    p.personal_distance_m =
        m.optional<double>("personal_distance", p.personal_distance_m, core::positive());
    p.body_radius_m = m.optional<double>("body_radius", p.body_radius_m, core::positive());
    m.finish();
  }
  if (entry.has("goal")) {
    const core::YamlMap goal = entry.map("goal");
    spec.goal = read_pose(goal);
    goal.finish();
  }
  if (entry.has("gaze")) {
    spec.gaze = read_gaze(entry.map("gaze"));
  }
  entry.finish();
  validate_entry(spec, entry);
  return spec;
}

GroupSpec parse_group(const core::YamlMap& entry) {
  GroupSpec spec;
  spec.id = entry.required<unsigned>("id", core::positive());
  spec.members = entry.required<std::vector<unsigned>>("members", core::positive());
  spec.centre = entry.required<Eigen::Vector2d>("centre");
  spec.ospace_radius_m = entry.optional<double>("ospace_radius", 0.0, core::non_negative());
  spec.member_spacing_m =
      entry.optional<double>("member_spacing", spec.member_spacing_m, core::positive());
  spec.social_distance_m =
      entry.optional<double>("social_distance", spec.social_distance_m, core::positive());
  entry.finish();
  validate_entry(spec, entry);
  return spec;
}

namespace {

AriSpec read_ari(const core::YamlMap& entry) {
  AriSpec spec;
  spec.id = entry.optional<unsigned>("id", spec.id, core::positive());
  spec.pose = read_pose(entry);
  spec.head_pan_rad = entry.optional<double>(
      "head_pan", 0.0,
      core::between(-spec.limits.head_pan_limit_rad, spec.limits.head_pan_limit_rad));
  spec.words_per_minute =
      entry.optional<double>("words_per_minute", spec.words_per_minute, core::positive());
  entry.finish();
  return spec;
}

}  // namespace

Scene parse_scene(const core::YamlMap& root, const std::string& base_dir) {
  Scene scene;
  scene.path = root.source();
  const std::string world = root.required<std::string>("world");
  const std::filesystem::path world_path = std::filesystem::path(world).is_absolute()
                                               ? std::filesystem::path(world)
                                               : std::filesystem::path(base_dir) / world;
  scene.world_path = world_path.lexically_normal().string();
  try {
    scene.world = model::load_world_file(scene.world_path);
  } catch (const core::ConfigError& e) {
    throw core::ConfigError(root.field_name("world") + ": " + e.what());
  }
  scene.seed = root.required<unsigned>("seed");
  if (root.has("ari")) {
    const core::YamlMap entry = root.map("ari");
    scene.ari = read_ari(entry);
    validate_entry(*scene.ari, entry);
  }
  const std::vector<core::YamlMap> humans = root.list("humans", true);
  if (humans.size() > kMaxHumans) {
    root.fail("humans", "at most " + std::to_string(kMaxHumans) + " humans",
              std::to_string(humans.size()));
  }
  for (const core::YamlMap& entry : humans) {
    scene.humans.push_back(parse_human(entry));
    scene.human_fields.push_back(entry.where());
  }
  const std::vector<core::YamlMap> groups = root.list("groups", true);
  if (groups.size() > kMaxSceneGroups) {
    root.fail("groups", "at most " + std::to_string(kMaxSceneGroups) + " groups",
              std::to_string(groups.size()));
  }
  for (const core::YamlMap& entry : groups) {
    scene.groups.push_back(parse_group(entry));
    scene.group_fields.push_back(entry.where());
  }
  // A scenario file is a scene file plus its script, which the scenario loader reads
  // (docs/scenario.md); here it only has to be a mapping.
  if (root.has("script")) {
    root.map("script");
  }
  root.finish();
  return scene;
}

Scene load_scene_file(const std::string& path) {
  return parse_scene(core::YamlMap::load_file(path),
                     std::filesystem::path(path).parent_path().string());
}

std::unique_ptr<Simulation> build_simulation(const Scene& scene, SimulationConfig config) {
  config.seed = scene.seed;
  auto simulation = std::make_unique<Simulation>(scene.world, config);
  try {
    if (scene.ari) {
      simulation->add_ari(*scene.ari);
    }
  } catch (const core::RequestError& e) {
    throw core::ConfigError(scene.path + ": ari: " + e.what());
  }
  // Gaze models are installed once everyone stands in the world: a human may look at people
  // listed after them.
  for (size_t i = 0; i < scene.humans.size(); ++i) {
    HumanSpec arriving = scene.humans[i];
    arriving.gaze.reset();
    try {
      simulation->add_human(arriving);
    } catch (const core::RequestError& e) {
      throw core::ConfigError(scene.human_fields[i] + ": " + e.what());
    }
  }
  for (size_t i = 0; i < scene.groups.size(); ++i) {
    try {
      simulation->add_group(scene.groups[i]);
    } catch (const core::RequestError& e) {
      throw core::ConfigError(scene.group_fields[i] + ": " + e.what());
    }
  }
  for (size_t i = 0; i < scene.humans.size(); ++i) {
    const std::optional<GazeModel>& gaze = scene.humans[i].gaze;
    if (!gaze) {
      continue;
    }
    try {
      // Checked first on its own, to word a refusal as the entry's field:
      // humans[0].gaze.targets[1].
      simulation->check_gaze_targets(RequestCheck(), scene.humans[i].id, *gaze);
      simulation->set_human_gaze(scene.humans[i].id, *gaze);
    } catch (const core::RequestError& e) {
      throw core::ConfigError(scene.human_fields[i] + ".gaze." + e.what());
    }
  }
  return simulation;
}

}  // namespace ari_social_sim::world
