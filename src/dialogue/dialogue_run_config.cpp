#include "ari_social_sim/dialogue/dialogue_run_config.hpp"

#include <algorithm>
#include <set>

#include "ari_social_sim/core/config_check.hpp"
#include "ari_social_sim/core/config_reader.hpp"
#include "ari_social_sim/core/error.hpp"

namespace ari_social_sim::dialogue {

const char* to_string(DialogueMode mode) {
  return core::choice_name(mode, kDialogueModes);
}

void DialogueRunConfig::validate() const {
  core::check_fields(*this, "DialogueRunConfig");
}

DialogueRunConfig DialogueRunConfig::from_yaml(const core::YamlMap& map) {
  return core::read_fields<DialogueRunConfig>(map);
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
