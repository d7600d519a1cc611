#include "ari_social_sim/dialogue/dialogue_run_config.hpp"

#include <algorithm>
#include <set>

#include "ari_social_sim/core/error.hpp"

namespace ari_social_sim::dialogue {

const char* to_string(DialogueMode mode) {
  switch (mode) {
    case DialogueMode::kWorld:
      return "world";
    case DialogueMode::kRlEnv:
      return "rl_env";
    case DialogueMode::kUserBot:
      return "user_bot";
  }
  return "?";
}

DialogueRunConfig DialogueRunConfig::from_yaml(const core::YamlMap& map) {
  DialogueRunConfig c;
  const std::string mode = map.required<std::string>("mode");
  if (mode == "world") {
    c.mode = DialogueMode::kWorld;
  } else if (mode == "rl_env") {
    c.mode = DialogueMode::kRlEnv;
  } else if (mode == "user_bot") {
    c.mode = DialogueMode::kUserBot;
  } else {
    map.fail("mode", "world, rl_env or user_bot", "'" + mode + "'");
  }
  c.config = map.optional<std::string>("config", c.config);
  c.seed = static_cast<uint64_t>(
      map.optional<int>("seed", static_cast<int>(c.seed), core::Bounds{0.0, 2147483647.0, false}));
  c.dialogues = map.optional<unsigned>("dialogues", c.dialogues);
  c.dialogue_pause_s =
      map.optional<double>("dialogue_pause", c.dialogue_pause_s, core::non_negative());
  c.live.robot_silence_s =
      map.optional<double>("robot_silence", c.live.robot_silence_s, core::positive());
  c.human_ids = map.optional<std::vector<unsigned>>("human_ids", c.human_ids);
  c.language = map.optional<std::string>("language", c.language);
  if (c.language.empty()) {
    map.fail("language", "an IETF language tag such as en-GB", "''");
  }
  c.humans = map.optional<bool>("humans", c.humans);
  const std::string start = map.optional<std::string>("start", "at_once");
  if (start == "at_once") {
    c.start = DialogueStart::kAtOnce;
  } else if (start == "robot_speaks") {
    c.start = DialogueStart::kRobotSpeaks;
  } else {
    map.fail("start", "at_once or robot_speaks", "'" + start + "'");
  }
  map.finish();
  return c;
}

void DialogueRunConfig::check_human_ids(const std::vector<std::string>& roles,
                                        const std::string& source) const {
  if (human_ids.empty()) {
    return;
  }
  std::set<unsigned> distinct(human_ids.begin(), human_ids.end());
  if (human_ids.size() != roles.size() || distinct.size() != human_ids.size() ||
      distinct.count(0) > 0) {
    std::string expected;
    for (const std::string& role : roles) {
      expected += (expected.empty() ? "" : ", ") + role;
    }
    throw core::ConfigError(source + ": human_ids: expected one distinct id > 0 per role (" +
                            expected + "), got " + std::to_string(human_ids.size()) + " ids");
  }
}

std::vector<uint32_t> DialogueRunConfig::cast(
    const std::vector<std::pair<uint32_t, std::string>>& humans,
    const std::vector<std::string>& roles, const std::string& world,
    const std::string& source) const {
  std::vector<uint32_t> ids;
  for (size_t r = 0; r < roles.size(); ++r) {
    const auto chosen = std::find_if(humans.begin(), humans.end(), [&](const auto& human) {
      return human_ids.empty() ? human.second == roles[r] : human.first == human_ids[r];
    });
    if (chosen == humans.end()) {
      throw core::ConfigError(
          human_ids.empty() ? world + ": no human with role '" + roles[r] +
                                  "' in the world; give " + source + ": human_ids"
                            : source + ": human_ids[" + std::to_string(r) + "]: no human with id " +
                                  std::to_string(human_ids[r]) + " in the world");
    }
    ids.push_back(chosen->first);
  }
  return ids;
}

}  // namespace ari_social_sim::dialogue
