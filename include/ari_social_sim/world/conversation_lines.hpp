#pragma once

#include <string>

#include "ari_social_sim/core/rng.hpp"

namespace ari_social_sim::world {

/// What a group member's next utterance is for, as the turn-taking of a conversation group
/// (group_conversation.hpp) decides it; the words come from a ConversationLines.
enum class LineKind {
  kStatement,      ///< small talk, to the group or to one member
  kQuestion,       ///< small talk that asks the addressee, who answers next
  kAnswer,         ///< the reply to a question
  kBackchannel,    ///< a listener's "mm-hm" during another's turn; takes no turn
  kRobotQuestion,  ///< a question to ARI from the dialogue domain (where, how, when, ...)
};

/// One utterance: the speech act the world records and the words it speaks.
struct ConversationLine {
  std::string act;
  std::string content;
};

/// Where conversation groups get their words: the conversational content generator
/// (world_speech::SmallTalkLines, small talk and the dialogue domain's topics). The world core
/// only decides who speaks, when, to whom and what kind of line; it draws the words from this
/// with the group's own generator, so the same seed gives the same transcript.
class ConversationLines {
 public:
  virtual ~ConversationLines() = default;

  /// A line of `kind`; `addressee_name` is the person (or "ARI") spoken to, empty when the
  /// speaker addresses the whole group. Never returns empty content (SpeechGenerator::say would
  /// refuse it).
  virtual ConversationLine line(LineKind kind, const std::string& addressee_name,
                                core::Rng& rng) const = 0;
};

}  // namespace ari_social_sim::world
