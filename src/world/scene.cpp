#include "ari_social_sim/world/scene.hpp"

#include <filesystem>

#include "ari_social_sim/core/config_reader.hpp"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/model/world_file.hpp"
#include "ari_social_sim/world/request_check.hpp"

namespace ari_social_sim::world {

HumanSpec parse_human(const core::YamlMap& entry) {
  return core::read_fields<HumanSpec>(entry);
}

GroupSpec parse_group(const core::YamlMap& entry) {
  return core::read_fields<GroupSpec>(entry);
}

WalkingGroupSpec parse_walking_group(const core::YamlMap& entry) {
  return core::read_fields<WalkingGroupSpec>(entry);
}

Scene parse_scene(const core::YamlMap& root, const std::string& base_dir) {
  const SceneFile file = core::read_fields<SceneFile>(root);
  Scene scene;
  scene.path = root.source();
  const std::filesystem::path world_path = std::filesystem::path(file.world).is_absolute()
                                               ? std::filesystem::path(file.world)
                                               : std::filesystem::path(base_dir) / file.world;
  scene.world_path = world_path.lexically_normal().string();
  try {
    scene.world = model::load_world_file(scene.world_path);
  } catch (const core::ConfigError& e) {
    throw core::ConfigError(root.field_name("world") + ": " + e.what());
  }
  scene.seed = file.seed;
  scene.ari = file.ari;
  scene.humans = file.humans;
  scene.groups = file.groups;
  scene.walking_groups = file.walking_groups;
  for (size_t i = 0; i < scene.humans.size(); ++i) {
    scene.human_fields.push_back(root.field_name("humans[" + std::to_string(i) + "]"));
  }
  for (size_t i = 0; i < scene.groups.size(); ++i) {
    scene.group_fields.push_back(root.field_name("groups[" + std::to_string(i) + "]"));
  }
  for (size_t i = 0; i < scene.walking_groups.size(); ++i) {
    scene.walking_group_fields.push_back(
        root.field_name("walking_groups[" + std::to_string(i) + "]"));
  }
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
  for (size_t i = 0; i < scene.walking_groups.size(); ++i) {
    try {
      simulation->add_walking_group(scene.walking_groups[i]);
    } catch (const core::RequestError& e) {
      throw core::ConfigError(scene.walking_group_fields[i] + ": " + e.what());
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
