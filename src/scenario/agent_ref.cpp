#include "ari_social_sim/scenario/agent_ref.hpp"

#include <cctype>
#include <limits>

namespace ari_social_sim::scenario {
namespace {

// A decimal id > 0 that fits an ObjectId, or kNoObject.
model::ObjectId parse_id(const std::string& text) {
  if (text.empty() || text.size() > 10 || text[0] == '0') {
    return model::kNoObject;
  }
  uint64_t value = 0;
  for (char c : text) {
    if (!std::isdigit(static_cast<unsigned char>(c))) {
      return model::kNoObject;
    }
    value = value * 10 + static_cast<uint64_t>(c - '0');
  }
  return value > std::numeric_limits<model::ObjectId>::max() ? model::kNoObject
                                                             : static_cast<model::ObjectId>(value);
}

}  // namespace

std::string AgentRef::describe() const {
  return is_ari() ? "ARI" : "human " + std::to_string(human_id);
}

std::optional<AgentRef> parse_agent_ref(const std::string& text) {
  if (text == "ari") {
    return AgentRef::ari();
  }
  const model::ObjectId id = parse_id(text);
  if (id == model::kNoObject) {
    return std::nullopt;
  }
  return AgentRef::human(id);
}

AgentRef read_agent_ref(const core::YamlMap& map, const std::string& key) {
  const std::string text = map.required<std::string>(key);
  const std::optional<AgentRef> ref = parse_agent_ref(text);
  if (!ref) {
    map.fail(key, "ari or a human id (a positive integer)", "'" + text + "'");
  }
  return *ref;
}

}  // namespace ari_social_sim::scenario
