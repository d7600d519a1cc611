#pragma once

#include <string>

#include "ari_social_sim/core/yaml_map.hpp"
#include "ari_social_sim/scenario/script.hpp"
#include "ari_social_sim/world/scene.hpp"

namespace ari_social_sim::scenario {

/// A scripted interaction (D6.4 §3.7): a scene (world file, seed, ARI, humans, groups; read by the
/// world's scene loader) plus a script, the state machine that drives the run. Read from
/// scenarios/*.yaml; the format is in docs/scenario.md.
struct Scenario {
  std::string name;  // the file's stem, e.g. group_discussion
  world::Scene scene;
  Script script;
};

/// Reads and checks a scenario file: the scene part as world::load_scene_file and
/// world::build_simulation do (so overlapping spawns are found here), then the script (every field,
/// every state name, every id against the scene and the humans the script adds). Throws
/// core::ConfigError naming the file and the entry, e.g. `scenarios/x.yaml:
/// script.states[2].transitions[0].when[1].distance: expected a number > 0, got -1`.
Scenario load_scenario_file(const std::string& path);
/// The same from a parsed mapping; `base_dir` resolves the world path, `name` names the scenario.
Scenario parse_scenario(const core::YamlMap& root, const std::string& base_dir,
                        const std::string& name);
/// The file a tool's --scenario names: a name without a slash or extension is one of the
/// package's scenarios, `scenario_dir/NAME.yaml`; anything else is a path as given.
std::string scenario_file_of(const std::string& name_or_file, const std::string& scenario_dir);

}  // namespace ari_social_sim::scenario
