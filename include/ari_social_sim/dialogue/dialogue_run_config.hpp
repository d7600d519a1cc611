#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ari_social_sim/core/yaml_map.hpp"
#include "ari_social_sim/dialogue/live_dialogue.hpp"

namespace ari_social_sim::dialogue {

/// The three ways dialogue_node runs (issue 5): content source for the world, RL environment as
/// ROS services, user bot speaking to a real conversational system as ASR would.
enum class DialogueMode { kWorld, kRlEnv, kUserBot };

/// `world`, `rl_env` or `user_bot`.
const char* to_string(DialogueMode mode);

/// How dialogue_node runs: its private parameters, read and checked in one place. Documented in
/// the README's parameter table.
struct DialogueRunConfig {
  DialogueMode mode{DialogueMode::kWorld};  // required
  std::string config;     // settings file; empty = the package's config/dialogue/simulation.yaml
  uint64_t seed{1};       // dialogue d runs with episode_seed(seed, d)
  unsigned dialogues{0};  // world, user_bot: dialogues to run, 0 = one after another forever
  double dialogue_pause_s{5.0};     // s between two dialogues
  LiveDialogueConfig live;          // robot_silence: s the humans wait for ARI before going on
  std::vector<unsigned> human_ids;  // world id per role of the settings (users.roles order); empty
                                    // = world: the lowest id with that role in the world;
                                    // user_bot: 1, 2, ...
  std::string language{"en-GB"};    // LiveSpeech language (user_bot)

  /// Reads every field from a mapping (parameter server or file); unknown keys, a missing or
  /// unknown mode and out-of-range values throw core::ConfigError naming the parameter.
  static DialogueRunConfig from_yaml(const core::YamlMap& map);
  /// Throws core::ConfigError unless human_ids is empty or has one distinct id > 0 per role.
  void check_human_ids(const std::vector<std::string>& roles, const std::string& source) const;
};

}  // namespace ari_social_sim::dialogue
