#pragma once

#include <actionlib/server/simple_action_server.h>
#include <ros/node_handle.h>
#include <ros/publisher.h>

#include "ari_social_sim/TtsAction.h"
#include "ari_social_sim/dialogue/spoken_dialogue.hpp"

namespace ari_social_sim::nodes {

/// Modes 1 and 3 over ROS: serves /tts (the TtsAction layout of pal_interaction_msgs) for a
/// dialogue::SpokenDialogue: a goal's rawtext is queued there, each word ARI starts is a
/// TTS_EVENT_STARTED_PLAYING_WORD feedback, and the goal succeeds once played; every utterance
/// goes to /sim/dialogue/utterances and each dialogue's end to /sim/dialogue/outcome.
/// Single-threaded: goal callbacks and tick() run on the one ROS spinner.
class LiveDialogueNode {
 public:
  /// Holds references to the setup, NLU, run config and stage, which must outlive it.
  LiveDialogueNode(ros::NodeHandle& nh, const dialogue::DialogueSetup& setup,
                   const dialogue::RobotNlu& nlu, const dialogue::DialogueRunConfig& run,
                   dialogue::SpeechStage& stage);

  /// Advances the dialogue to the stage's clock; call on every tick of the stage.
  void tick();

 private:
  void on_goal();
  void on_preempt();
  void publish(const dialogue::SpokenDialogueEvents& events);

  dialogue::SpokenDialogue dialogue_;
  actionlib::SimpleActionServer<TtsAction> tts_;
  ros::Publisher utterance_pub_, outcome_pub_;
};

}  // namespace ari_social_sim::nodes
