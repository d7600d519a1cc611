#pragma once

#include <ros/node_handle.h>
#include <ros/publisher.h>

#include <string>
#include <vector>

#include "ari_social_sim/dialogue/speech_stage.hpp"
#include "ari_social_sim/dialogue/turn_timing.hpp"

namespace ari_social_sim::nodes {

/// Mode 3: the simulated humans heard the way a real conversational system hears people, through
/// ROS4HRI (REP-155): per voice `/humans/voices/<voice>/speech` (hri_msgs/LiveSpeech:
/// incremental hypotheses word by word, then the final text with its confidence and language) and
/// `is_speaking`; `/humans/voices/tracked` and `/humans/persons/tracked` (10 Hz, latched);
/// latched `/humans/persons/<person>/voice_id` and `anonymous`. What is published is what ARI
/// perceives after the error layer: ASR-like text, the confidence, a dropped utterance not at all,
/// a misattributed one under the other human's voice. Utterances last the turn timing's duration
/// on ROS time; ARI's /tts words take the same rate.
class AsrStage : public dialogue::SpeechStage {
 public:
  /// `roles` and `human_ids` in the same order; ids give person ids `human<N>`, voices `voice<N>`.
  AsrStage(ros::NodeHandle& nh, const dialogue::TurnTiming& timing, std::vector<std::string> roles,
           std::vector<uint32_t> human_ids, std::string language);

  double now_s() const override;
  /// Something subscribes to a voice's speech: the users do not talk to an empty room.
  bool has_listener() const override;
  void start_human(const dialogue::Utterance& utterance, size_t human) override;
  bool human_done() override;
  void start_robot(const std::string& text) override;
  size_t robot_words_started() override;
  bool robot_done() override;
  uint32_t human_id(size_t human) const override { return human_ids_.at(human); }
  uint32_t robot_id() const override { return 0; }

  /// Publishes the tracked voices and persons (every human is always tracked).
  void publish_tracked();

 private:
  struct Voice {
    std::string id;
    ros::Publisher speech, is_speaking;
  };

  void publish_speech(size_t voice, const std::string& incremental, const std::string& final_text,
                      double confidence);

  const dialogue::TurnTiming& timing_;
  std::vector<std::string> roles_;
  std::vector<uint32_t> human_ids_;
  std::string language_;
  std::vector<Voice> voices_;
  std::vector<ros::Publisher> person_topics_;  ///< latched; kept alive for late subscribers
  ros::Publisher voices_tracked_, persons_tracked_;

  // The human utterance being heard.
  bool human_playing_{false};
  int heard_voice_{-1};  ///< -1: dropped, nothing is published
  std::vector<std::string> heard_words_;
  double heard_confidence_{0.0};
  double human_start_s_{0.0};
  double human_duration_s_{0.0};
  size_t words_published_{0};

  // ARI's utterance.
  double robot_start_s_{0.0};
  double robot_duration_s_{0.0};
  size_t robot_word_count_{0};
};

/// The voice id dialogue_node gives the simulated human with world id `id` in mode 3.
inline std::string voice_id(uint32_t id) {
  return "voice" + std::to_string(id);
}

}  // namespace ari_social_sim::nodes
