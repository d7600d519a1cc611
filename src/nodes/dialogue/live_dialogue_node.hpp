#pragma once

#include <actionlib/server/simple_action_server.h>
#include <ros/node_handle.h>
#include <ros/publisher.h>

#include <string>

#include "ari_social_sim/TtsAction.h"
#include "ari_social_sim/dialogue/dialogue_run_config.hpp"
#include "ari_social_sim/dialogue/live_dialogue.hpp"
#include "dialogue/speech_stage.hpp"

namespace ari_social_sim::nodes {

/// Modes 1 and 3: simulated humans in a dialogue with a live robot. Serves /tts (the TtsAction
/// layout of pal_interaction_msgs): a goal's rawtext waits for the floor, is voiced by the stage
/// word by word (feedback TTS_EVENT_STARTED_PLAYING_WORD per word) and succeeds once played;
/// what ARI said goes to the LiveDialogue, whose human replies the stage voices in turn.
/// Publishes every utterance on /sim/dialogue/utterances and each dialogue's end on
/// /sim/dialogue/outcome; runs `dialogues` dialogues (0 = forever), `dialogue_pause` apart, each
/// once the stage has a listener.
/// Single-threaded: goal callbacks and tick() run on the one ROS spinner.
class LiveDialogueNode {
 public:
  /// Holds references to the setup, NLU, run config and stage, which must outlive it.
  LiveDialogueNode(ros::NodeHandle& nh, const dialogue::DialogueSetup& setup,
                   const dialogue::RobotNlu& nlu, const dialogue::DialogueRunConfig& run,
                   SpeechStage& stage);

  /// Advances the dialogue to the stage's clock; call on every tick of the stage.
  void tick();

 private:
  void on_goal();
  void on_preempt();
  void start_dialogue(double now_s);
  void finish_robot(const std::string& said, double now_s);
  void publish_utterance(int index, double stamp_s);
  void publish_outcome(double now_s);
  std::string robot_words(size_t count) const;

  const dialogue::DialogueSetup& setup_;
  const dialogue::DialogueRunConfig& run_;
  SpeechStage& stage_;
  dialogue::LiveDialogue live_;

  uint32_t dialogue_index_{0};
  bool dialogue_active_{false};
  double next_start_s_{-1.0};  ///< when the next dialogue starts; < 0 = none left
  bool human_playing_{false};

  // ARI's current /tts goal: waiting for the floor, then speaking.
  bool robot_waiting_{false};
  bool robot_speaking_{false};
  std::string robot_text_;
  std::vector<std::string> robot_word_list_;
  double robot_not_before_s_{0.0};
  double robot_start_s_{0.0};
  size_t robot_words_reported_{0};

  actionlib::SimpleActionServer<TtsAction> tts_;
  ros::Publisher utterance_pub_, outcome_pub_;
};

}  // namespace ari_social_sim::nodes
