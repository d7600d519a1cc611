#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "ari_social_sim/core/yaml_map.hpp"
#include "ari_social_sim/dialogue/live_dialogue.hpp"

namespace ari_social_sim::dialogue {

/// The three ways dialogue_node runs (issue 5): content source for the world, RL environment as
/// ROS services, user bot speaking to a real conversational system as ASR would.
enum class DialogueMode { kWorld, kRlEnv, kUserBot };

/// `world`, `rl_env` or `user_bot`.
const char* to_string(DialogueMode mode);

/// When a dialogue starts: at once (the humans may open it), or when ARI first speaks (ARI opens
/// it, as when a robot walks up to people).
enum class DialogueStart { kAtOnce, kRobotSpeaks };

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
  bool humans{true};  // world: false = no simulated humans, /tts only voices ARI (scripted scenes)
  DialogueStart start{DialogueStart::kAtOnce};  // `at_once` or `robot_speaks`

  /// Reads every field from a mapping (parameter server or file); unknown keys, a missing or
  /// unknown mode and out-of-range values throw core::ConfigError naming the parameter.
  static DialogueRunConfig from_yaml(const core::YamlMap& map);
  /// Throws core::ConfigError unless human_ids is empty or has one distinct id > 0 per role.
  void check_human_ids(const std::vector<std::string>& roles, const std::string& source) const;
  /// World mode: the world id of the human playing each role, from the world's humans (id and
  /// role, ordered by id): human_ids when given (each must exist), else the lowest id with the
  /// role. Throws core::ConfigError naming `world` or `source` otherwise.
  std::vector<uint32_t> cast(const std::vector<std::pair<uint32_t, std::string>>& humans,
                             const std::vector<std::string>& roles, const std::string& world,
                             const std::string& source) const;
};

}  // namespace ari_social_sim::dialogue
