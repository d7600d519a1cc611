#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "ari_social_sim/core/rng.hpp"
#include "ari_social_sim/dialogue/dialogue_config.hpp"
#include "ari_social_sim/dialogue/rule_policy.hpp"
#include "ari_social_sim/scenario/hearing.hpp"
#include "ari_social_sim/scenario/observations.hpp"
#include "ari_social_sim/scenario/recognised_speech.hpp"
#include "ari_social_sim/scenario/script.hpp"

namespace ari_social_sim::scenario {

/// ARI's side of a dialogue with the simulated humans (a script's `converse`): the dialogue core's
/// rule-based policy answers what ARI heard and the NLG puts its acts into words, for the script
/// to say through ARI's /tts. ARI takes a turn only when nobody in the world is speaking and its
/// previous utterance has been played, and opens with the policy's greeting. ARI hears the people
/// as `hearing` says: the dialogue's simulated perceptions, or the recognised transcripts
/// (RecognisedSpeech). Holds references to the dialogue setup, which must outlive it.
class Conversation {
 public:
  /// `seed` draws the NLG's choices of words.
  Conversation(const dialogue::DialogueSetup& setup, uint64_t seed, Hearing hearing);

  /// ARI joins the dialogue: the policy starts afresh and ARI's first turn is its opening.
  void start();
  void stop() { active_ = false; }
  bool active() const { return active_; }

  /// Takes in what ARI heard; returns what ARI says now, if anything (the caller says it).
  std::optional<SayAction> update(const Observations& observations);

  int robot_turns() const { return robot_turns_; }

 private:
  bool floor_free(const world::WorldSnapshot& world) const;

  const dialogue::DialogueSetup& setup_;
  dialogue::RulePolicy policy_;
  core::Rng rng_;
  std::optional<RecognisedSpeech> recognised_;  // set when ARI hears the recogniser
  std::vector<dialogue::Perception> pending_;   // heard since ARI's last turn
  bool active_{false};
  bool opening_{false};
  int robot_turns_{0};
  // ARI's last utterance: sent, then seen playing, then over.
  enum class Own { kNone, kSent, kPlaying } own_{Own::kNone};
};

}  // namespace ari_social_sim::scenario
