#include "ari_social_sim/learning/conversation_task.hpp"

#include <algorithm>
#include <string>
#include <utility>

namespace ari_social_sim::learning {
namespace {

// ARI's lines: the task judges when ARI speaks, not what it says, so the words are fixed; the
// group's conversation only observes that ARI speaks (GroupConversation).
struct Line {
  const char* act;
  const char* content;
};
constexpr Line kGreeting{"greet", "Hello, may I join you?"};
constexpr Line kAnswer{"inform", "Let me help you with that."};
constexpr Line kRemark{"acknowledge", "I see."};
constexpr float kSpeakThreshold = 0.5f;

const world::GroupSnapshot* find_group(const world::WorldSnapshot& snapshot, model::ObjectId id) {
  for (const world::GroupSnapshot& group : snapshot.groups) {
    if (group.id == id) {
      return &group;
    }
  }
  return nullptr;
}

}  // namespace

ConversationTask::ConversationTask(const ConversationTaskConfig& config, model::ObjectId group,
                                   std::vector<model::ObjectId> members)
    : config_(config), group_(group), members_(std::move(members)) {}

navigation::ObservationField ConversationTask::field(int offset) {
  return {"conversation", offset, kObservationSize, 0.0f, kSilenceClipS};
}

bool ConversationTask::is_member(model::ObjectId id) const {
  return std::find(members_.begin(), members_.end(), id) != members_.end();
}

double ConversationTask::act(world::Simulation& sim, float speak, const RewardWeights& weights) {
  if (speak <= kSpeakThreshold || ari_speaking_ || sim.ari() == nullptr) {
    return 0.0;
  }
  double reward = 0.0;
  Line line = greeted_ ? kRemark : kGreeting;
  if (question_end_s_ >= 0.0) {
    line = kAnswer;
    if (now_s_ <= question_end_s_ + config_.answer_window_s) {
      ++metrics_.answers;
      reward += weights.answer;
      if (metrics_.answer_delay_s < 0.0) {
        metrics_.answer_delay_s = std::max(0.0, now_s_ - question_end_s_);
      }
    }
    question_end_s_ = -1.0;
  }
  greeted_ = true;
  sim.say(sim.ari()->id(), line.act, line.content);
  ari_speaking_ = true;
  ++metrics_.ari_lines;
  if (member_floor_) {
    ++metrics_.interruptions;
    reward += weights.interruption;
  }
  metrics_.success = metrics_.joined && metrics_.answers > 0;
  return reward;
}

double ConversationTask::observe(const world::WorldSnapshot& snapshot,
                                 const RewardWeights& weights) {
  conversation_.observe(snapshot);
  now_s_ = snapshot.time_s;
  ari_ = snapshot.ari ? snapshot.ari->id : model::kNoObject;
  ari_speaking_ = snapshot.ari && snapshot.ari->speech.is_speaking;
  const world::GroupSnapshot* group = find_group(snapshot, group_);
  double reward = 0.0;
  const bool joined = group && snapshot.ari && group->robot_joining == snapshot.ari->id;
  if (joined && !metrics_.joined) {
    ++metrics_.entries;
    // The floor as it was when ARI moved in: that of the state before this one.
    if (member_floor_) {
      ++metrics_.intrusions;
      reward += weights.intrusion;
    }
  }
  metrics_.joined = joined;
  member_floor_ = group && is_member(group->speaker);
  if (member_floor_) {
    last_member_end_s_ = group->utterance_end_s;
    const bool to_ari = snapshot.ari && group->addressee == snapshot.ari->id;
    if (to_ari && group->utterance_end_s != counted_question_end_s_) {
      counted_question_end_s_ = group->utterance_end_s;
      question_end_s_ = group->utterance_end_s;
      ++metrics_.questions;
    }
  }
  metrics_.success = metrics_.joined && metrics_.answers > 0;
  summarise();
  return reward;
}

void ConversationTask::hear(const perception::PerceptionFrame& frame) {
  member_heard_ = std::any_of(frame.voices.begin(), frame.voices.end(),
                              [&](const perception::PerceivedVoice& voice) {
                                return voice.is_speaking && is_member(voice.human);
                              });
}

void ConversationTask::write_observation(float* out) const {
  const double silence_s = member_floor_ ? 0.0 : std::max(0.0, now_s_ - last_member_end_s_);
  out[0] = member_heard_ ? 1.0f : 0.0f;
  out[1] = question_end_s_ >= 0.0 ? 1.0f : 0.0f;
  out[2] = std::min(static_cast<float>(silence_s), kSilenceClipS);
  out[3] = ari_speaking_ ? 1.0f : 0.0f;
}

void ConversationTask::summarise() {
  metrics_.group_talk = world::ConversationFigures::of(conversation_.summary(), ari_);
}

}  // namespace ari_social_sim::learning
