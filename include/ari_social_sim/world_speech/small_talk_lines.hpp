#pragma once

#include <memory>
#include <string>

#include "ari_social_sim/dialogue/domain.hpp"
#include "ari_social_sim/dialogue/nlg.hpp"
#include "ari_social_sim/dialogue/small_talk.hpp"
#include "ari_social_sim/world/conversation_lines.hpp"

namespace ari_social_sim::world_speech {

/// The conversational content generator behind the world's conversation groups: small talk
/// among the members (dialogue::SmallTalk) and, to ARI, the dialogue domain's requests as the
/// NLG's human side words them (a goal drawn from the domain, one of its ask acts realised).
/// Installed by world_node and the engine (Simulation::set_conversation_lines).
class SmallTalkLines : public world::ConversationLines {
 public:
  SmallTalkLines(dialogue::SmallTalk talk, dialogue::Domain domain, dialogue::Nlg nlg);

  /// The package's files under `config_dir`: dialogue/small_talk.yaml, dialogue/
  /// hospital_domain.yaml and dialogue/nlg_templates.yaml. Throws core::ConfigError naming the
  /// file and field.
  static std::shared_ptr<const SmallTalkLines> load(const std::string& config_dir);

  world::ConversationLine line(world::LineKind kind, const std::string& addressee_name,
                               core::Rng& rng) const override;

 private:
  world::ConversationLine robot_question(core::Rng& rng) const;

  dialogue::SmallTalk talk_;
  dialogue::Domain domain_;
  dialogue::Nlg nlg_;
};

}  // namespace ari_social_sim::world_speech
