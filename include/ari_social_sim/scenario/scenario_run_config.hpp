#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "ari_social_sim/core/config_fields.hpp"
#include "ari_social_sim/core/yaml_map.hpp"
#include "ari_social_sim/scenario/hearing.hpp"
#include "ari_social_sim/scenario/script_time_limit.hpp"

namespace ari_social_sim::scenario {

/// How scenario_node runs a scenario: its private parameters, listed once in visit
/// (core/config_fields.hpp; docs/parameters.md is generated from it).
struct ScenarioRunConfig {
  std::string scenario;
  std::optional<uint64_t> seed;
  double server_timeout_s{60.0};
  double group_timeout_s{1.0};
  std::string dialogue_config;
  bool start_world{true};
  std::optional<double> time_limit_s;
  std::optional<double> wall_time_limit_s;
  double world_timeout_s{10.0};
  Hearing hearing{Hearing::kSimulated};

  template <class V>
  void visit(V& v) {
    v.field(core::required("scenario"), scenario, "the scenario file");
    v.field(core::unset_by_minus_one("seed"), seed,
            "seed of the script's random draws (random groups); unset: the scene's",
            core::kParameterSeedBounds);
    v.field("server_timeout", server_timeout_s,
            "wall seconds to wait for the services and actions the script uses", core::positive());
    // ROS4HRI publishes one message per group, repeatedly, and no "gone" message.
    v.field("group_timeout", group_timeout_s,
            "sim seconds after which a perceived group not published again counts as gone",
            core::positive());
    v.field("dialogue_config", dialogue_config,
            "dialogue settings of ARI's `converse` (its policy's domain and NLG), read only by "
            "scripts that converse; empty: the package's config/dialogue/simulation.yaml");
    v.field("start_world", start_world,
            "unpause the world once everything the script uses is up; false leaves that to "
            "another node (a test that must see every state, a user's rqt)");
    v.field("time_limit", time_limit_s,
            "sim seconds after which the script ends as a failure, in place of the scenario "
            "file's script time_limit (a shorter run, or a failure on purpose: `time_limit:=3` "
            "of the scenario launches); unset: the file's",
            script_time_limit_bounds());
    // The script's time_limit counts sim time, which stands still when the world is paused or
    // gone.
    v.field("wall_time_limit", wall_time_limit_s,
            "wall seconds after which the run ends as a failure whatever it is doing, waits for "
            "servers and the world included; unset: 3 x the script's time_limit + "
            "server_timeout (the script at a third of real time); 0: no limit",
            core::non_negative());
    v.field("world_timeout", world_timeout_s,
            "wall seconds without a /sim/world_state while the world should run (after the node "
            "unpaused it, or from the first state when another node starts it) after which the "
            "run ends as a failure naming the wait",
            core::positive());
    v.choice("hearing", hearing,
             "what ARI's `converse` hears the people by: simulated (dialogue_node's perceptions, "
             "acts through the error layer) or recognised (the final transcripts of "
             "/humans/voices/<id>/speech, understood by ARI's own NLU; speech:=audio)",
             kHearings);
  }

  /// The script's sim-time limit: the time_limit parameter if set, else the file's.
  double script_time_limit_for(double file_time_limit_s) const;

  /// The wall-time limit for a script with this sim-time limit: the parameter if set (0 = none),
  /// else 3 x the script's limit (the script at a third of real time) + server_timeout (the
  /// wait for the suite).
  double wall_time_limit_for(double script_time_limit_s) const;

  /// Throws core::ConfigError naming the field outside what visit allows (an empty scenario too).
  void validate() const;
  /// Reads every field; unknown keys and out-of-range values throw core::ConfigError naming the
  /// parameter.
  static ScenarioRunConfig from_yaml(const core::YamlMap& map);
};

}  // namespace ari_social_sim::scenario
