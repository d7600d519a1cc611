#pragma once

#include <optional>
#include <string>

#include "ari_social_sim/core/yaml_map.hpp"
#include "ari_social_sim/model/object_id.hpp"

namespace ari_social_sim::scenario {

/// Who a script line is about: ARI or one simulated human, by its world id. Written `ari` or the
/// human's id in scenario files.
struct AgentRef {
  model::ObjectId human_id{model::kNoObject};  // kNoObject means ARI

  static AgentRef ari() { return {}; }
  static AgentRef human(model::ObjectId id) { return {id}; }
  bool is_ari() const { return human_id == model::kNoObject; }
  /// `ARI` or `human 11`, for messages and transcripts.
  std::string describe() const;

  bool operator==(const AgentRef& other) const { return human_id == other.human_id; }
  bool operator!=(const AgentRef& other) const { return !(*this == other); }
  bool operator<(const AgentRef& other) const { return human_id < other.human_id; }
};

/// `ari` or a positive human id; nothing for any other text.
std::optional<AgentRef> parse_agent_ref(const std::string& text);
/// Reads `key` as `ari` or a positive human id. Throws core::ConfigError naming the field.
AgentRef read_agent_ref(const core::YamlMap& map, const std::string& key);

}  // namespace ari_social_sim::scenario
