#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "ari_social_sim/core/config_fields.hpp"
#include "ari_social_sim/core/yaml_map.hpp"
#include "ari_social_sim/dialogue/live_dialogue.hpp"

namespace ari_social_sim::dialogue {

/// The three ways dialogue_node runs (issue 5): content source for the world, RL environment as
/// ROS services, user bot speaking to a real conversational system as ASR would.
enum class DialogueMode { kWorld, kRlEnv, kUserBot };

inline constexpr core::Choice<DialogueMode> kDialogueModes[] = {
    {DialogueMode::kWorld, "world"},
    {DialogueMode::kRlEnv, "rl_env"},
    {DialogueMode::kUserBot, "user_bot"}};

/// `world`, `rl_env` or `user_bot`.
const char* to_string(DialogueMode mode);

/// When a dialogue starts: at once (the humans may open it), or when ARI first speaks (ARI opens
/// it, as when a robot walks up to people).
enum class DialogueStart { kAtOnce, kRobotSpeaks };

inline constexpr core::Choice<DialogueStart> kDialogueStarts[] = {
    {DialogueStart::kAtOnce, "at_once"}, {DialogueStart::kRobotSpeaks, "robot_speaks"}};

/// How dialogue_node runs: its private parameters, listed once in visit (core/config_fields.hpp;
/// docs/parameters.md is generated from it).
struct DialogueRunConfig {
  DialogueMode mode{DialogueMode::kWorld};
  std::string config;
  uint64_t seed{1};
  unsigned dialogues{0};
  double dialogue_pause_s{5.0};
  LiveDialogueConfig live;
  std::vector<unsigned> human_ids;
  std::string language{"en-GB"};
  bool humans{true};
  DialogueStart start{DialogueStart::kAtOnce};

  template <class V>
  void visit(V& v) {
    v.choice(core::required("mode"), mode,
             "world: content source for the world; rl_env: RL environment as services; "
             "user_bot: simulated users speaking to a real conversational system",
             kDialogueModes);
    v.field("config", config,
            "dialogue settings (config/dialogue/simulation.yaml below); empty: the package's");
    v.field("seed", seed, "dialogue d runs with its own seed drawn from (seed, d)",
            core::Bounds{0.0, 2147483647.0, false});
    v.field("dialogues", dialogues,
            "world, user_bot: dialogues to run one after another; 0 = forever");
    v.field("dialogue_pause", dialogue_pause_s, "s between two dialogues", core::non_negative());
    live.visit(v);
    v.field("human_ids", human_ids,
            "world ids of the humans, one per role of the settings (users.roles); empty: in "
            "world mode the lowest id with the role, in user_bot mode 1, 2, ...");
    v.field("language", language, "`language` of the LiveSpeech messages (user_bot)");
    v.rule("language", !language.empty(), "an IETF language tag such as en-GB", "''");
    v.field("humans", humans,
            "world: false = no simulated humans, /tts only voices ARI (scripted scenes)");
    v.choice("start", start,
             "at_once: the humans may open the dialogue; robot_speaks: it starts when ARI first "
             "speaks",
             kDialogueStarts);
  }

  /// Throws core::ConfigError naming the field outside what visit allows.
  void validate() const;
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
