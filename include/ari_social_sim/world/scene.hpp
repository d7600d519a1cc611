#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ari_social_sim/core/yaml_map.hpp"
#include "ari_social_sim/model/world_description.hpp"
#include "ari_social_sim/world/ari.hpp"
#include "ari_social_sim/world/group_navigation.hpp"
#include "ari_social_sim/world/human.hpp"
#include "ari_social_sim/world/simulation.hpp"

namespace ari_social_sim::world {

/// Most groups one scene file may list (each needs members of its own, so at most one per human).
constexpr size_t kMaxSceneGroups = kMaxHumans;

/// A scene file's keys (config_fields.hpp), as parse_scene reads them before loading the world.
struct SceneFile {
  std::string world;
  uint64_t seed{0};
  std::optional<AriSpec> ari;
  std::vector<HumanSpec> humans;
  std::vector<GroupSpec> groups;
  std::vector<WalkingGroupSpec> walking_groups;
  std::optional<core::YamlMap> script;

  template <class V>
  void visit(V& v) {
    v.field(core::required("world"), world,
            "the world file (walls, furniture), relative to the scene file's folder");
    v.field(core::required("seed"), seed,
            "seed of every random draw of the run (gaze, speech, perception errors)");
    v.section("ari", ari, "ARI, when the scene has it");
    v.list("humans", humans, "the people at the start", kMaxHumans);
    v.list("groups", groups, "conversation groups of those people", kMaxSceneGroups);
    v.list("walking_groups", walking_groups, "people walking together to a goal", kMaxSceneGroups);
    v.field("script", script, "a scenario's script (docs/scenario.md); scene files have none");
  }
};

/// Who is in a world at the start of a run: the world file, the seed, ARI, humans and groups.
/// Read from scenes/*.yaml (format in docs/world.md). Scenario files (scenarios/*.yaml,
/// docs/scenario.md) are scene files with a `script` section, which this loader leaves to the
/// scenario loader, so world_node plays a scenario's scene directly.
struct Scene {
  std::string path;        // the scene file, for messages
  std::string world_path;  // resolved path of the world file
  model::WorldDescription world;
  uint64_t seed{0};
  std::optional<AriSpec> ari;
  std::vector<HumanSpec> humans;
  std::vector<GroupSpec> groups;
  std::vector<WalkingGroupSpec> walking_groups;
  /// Where each human and group was written (`scene.yaml: humans[2]`), for errors found later.
  std::vector<std::string> human_fields;
  std::vector<std::string> group_fields;
  std::vector<std::string> walking_group_fields;
};

/// Reads a scene file; `world:` is resolved relative to the scene file's folder. Throws
/// core::ConfigError naming the file, the entry and the field; a scene lists at most kMaxHumans
/// humans and kMaxSceneGroups groups, a group at most kMaxGroupMembers members, a gaze model at
/// most kMaxGazeTargets targets (and the file is read only within core::kMaxYamlFileBytes).
Scene load_scene_file(const std::string& path);
/// The same from a parsed mapping; `base_dir` resolves the world path.
Scene parse_scene(const core::YamlMap& root, const std::string& base_dir);

/// Reads and validates one `humans[i]` entry (docs/world.md section 3.3). Throws
/// core::ConfigError naming the entry and the field.
HumanSpec parse_human(const core::YamlMap& entry);
/// The same for one `groups[i]` entry (section 3.6).
GroupSpec parse_group(const core::YamlMap& entry);
/// The same for one `walking_groups[i]` entry (docs/world.md "Walking groups").
WalkingGroupSpec parse_walking_group(const core::YamlMap& entry);

/// Builds the simulation a scene describes. Errors found only when placing bodies (overlapping
/// spawn positions, unknown group members, ids used twice) throw core::ConfigError naming the
/// scene file and entry.
std::unique_ptr<Simulation> build_simulation(const Scene& scene, SimulationConfig config);

}  // namespace ari_social_sim::world
