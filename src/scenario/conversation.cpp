#include "ari_social_sim/scenario/conversation.hpp"

namespace ari_social_sim::scenario {
namespace {

// How far (m) from ARI a speaker holds the floor of ARI's conversation: a conversation group
// stands within it, a group talking across the room does not.
constexpr double kConversationRangeM = 3.0;

}  // namespace

Conversation::Conversation(const dialogue::DialogueSetup& setup, uint64_t seed, Hearing hearing)
    : setup_(setup), policy_(setup.domain), rng_(seed) {
  if (hearing == Hearing::kRecognised) {
    recognised_.emplace(setup);
  }
}

void Conversation::start() {
  policy_.reset();
  pending_.clear();
  active_ = true;
  opening_ = true;
  robot_turns_ = 0;
  own_ = Own::kNone;
}

bool Conversation::floor_free(const world::WorldSnapshot& world) const {
  if (world.ari && world.ari->speech.is_speaking) {
    return false;
  }
  // Only those within conversation range of ARI: people talking across the room hold no floor of
  // ARI's conversation.
  for (const world::HumanSnapshot& human : world.humans) {
    const bool near =
        !world.ari || (human.pose.position - world.ari->pose.position).norm() < kConversationRangeM;
    if (near && human.speech.is_speaking) {
      return false;
    }
  }
  return true;
}

std::optional<SayAction> Conversation::update(const Observations& observations) {
  if (!active_) {
    return std::nullopt;
  }
  if (observations.dialogue_end) {
    active_ = false;
    return std::nullopt;
  }
  if (recognised_) {
    recognised_->hear(observations.transcripts, pending_);
  } else {
    pending_.insert(pending_.end(), observations.heard.begin(), observations.heard.end());
  }
  // ARI's own utterance must have played before it takes another turn (live, /tts waits for the
  // floor, so it may start late).
  const bool ari_speaking = observations.world.ari && observations.world.ari->speech.is_speaking;
  if (own_ == Own::kSent && ari_speaking) {
    own_ = Own::kPlaying;
  } else if (own_ == Own::kPlaying && !ari_speaking) {
    own_ = Own::kNone;
  }
  if (own_ != Own::kNone || !floor_free(observations.world) || (!opening_ && pending_.empty())) {
    return std::nullopt;
  }
  dialogue::Observation heard;
  heard.heard = std::move(pending_);
  heard.robot_turn = robot_turns_;
  pending_.clear();
  opening_ = false;
  const dialogue::RobotAction action = policy_.act(heard);
  if (action.acts.empty()) {
    return std::nullopt;  // nothing addressed to ARI: it lets the humans go on
  }
  ++robot_turns_;
  own_ = Own::kSent;
  return SayAction{AgentRef::ari(), dialogue::acts_to_string(action.acts),
                   setup_.nlg->realise(true, action.acts, rng_)};
}

}  // namespace ari_social_sim::scenario
