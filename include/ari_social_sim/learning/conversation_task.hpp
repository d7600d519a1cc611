#pragma once

#include <vector>

#include "ari_social_sim/learning/nav_task_config.hpp"
#include "ari_social_sim/model/object_id.hpp"
#include "ari_social_sim/navigation/policy_observation.hpp"
#include "ari_social_sim/perception/perception_frame.hpp"
#include "ari_social_sim/world/conversation_metrics.hpp"
#include "ari_social_sim/world/simulation.hpp"
#include "ari_social_sim/world/world_snapshot.hpp"

namespace ari_social_sim::learning {

/// What a join_conversation episode did: world::ConversationMetrics' figures under run_episodes'
/// CSV column names, and the task's own counts.
struct ConversationTaskMetrics {
  world::ConversationFigures group_talk;
  int ari_lines{0};             // lines ARI began
  int interruptions{0};         // of them, begun while a member held the floor
  int entries{0};               // times the formation took ARI in
  int intrusions{0};            // of them, while a member held the floor
  int questions{0};             // members' utterances addressed to ARI
  int answers{0};               // ARI's lines begun within answer_window of a question's end
  double answer_delay_s{-1.0};  // from the first question's end to ARI's answer; -1: none
  bool joined{false};           // the formation counts ARI now
  bool success{false};          // joined and answered
};

/// The conversation part of join_conversation, beside NavEnv's navigation: ARI's lines (the
/// `speak` action, said through the world's say path as /sim/say and the dialogue's TTS are), the
/// reward terms judged on the world's floor, the observation's `conversation` part and the
/// metrics. The group is found by id in the world's states; its conversation and words are the
/// world's (Simulation::set_conversation_lines).
class ConversationTask {
 public:
  static constexpr int kObservationSize = 4;
  /// Seconds since a member's utterance ended are clipped here: longer pauses look alike.
  static constexpr float kSilenceClipS = 10.0f;

  ConversationTask(const ConversationTaskConfig& config, model::ObjectId group,
                   std::vector<model::ObjectId> members);

  /// The observation's `conversation` part: its name, offset after `offset`, bounds.
  static navigation::ObservationField field(int offset);

  /// Before a world step: with `speak` > 0.5 and ARI silent, ARI begins its next line (an answer
  /// when a question to it is pending, else a greeting first, then a remark). The reward of the
  /// interruption and answer terms.
  double act(world::Simulation& sim, float speak, const RewardWeights& weights);
  /// After a world step, on its state: entries, questions, the metrics. The intrusion term.
  double observe(const world::WorldSnapshot& snapshot, const RewardWeights& weights);
  /// Perception's voices of the step: whether one of the members is heard speaking.
  void hear(const perception::PerceptionFrame& frame);
  void write_observation(float* out) const;

  const ConversationTaskMetrics& metrics() const { return metrics_; }

 private:
  bool is_member(model::ObjectId id) const;
  void summarise();

  ConversationTaskConfig config_;
  model::ObjectId group_;
  std::vector<model::ObjectId> members_;
  world::ConversationMetrics conversation_;
  ConversationTaskMetrics metrics_;
  double now_s_{0.0};
  model::ObjectId ari_{model::kNoObject};
  bool member_floor_{false};  // truth: a member holds the floor
  bool member_heard_{false};  // perception: a member's voice is speaking
  bool ari_speaking_{false};
  bool greeted_{false};
  double last_member_end_s_{0.0};        // end of the last member utterance seen
  double question_end_s_{-1.0};          // of the pending question to ARI; -1: none
  double counted_question_end_s_{-1.0};  // of the last question counted, so each counts once
};

}  // namespace ari_social_sim::learning
