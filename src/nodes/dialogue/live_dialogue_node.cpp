#include "live_dialogue_node.hpp"

#include "ari_social_sim/DialogueOutcome.h"
#include "ari_social_sim/DialogueUtterance.h"
#include "ari_social_sim/core/error.hpp"
#include "dialogue_conversions/dialogue.hpp"
#include "request_checks.hpp"

namespace ari_social_sim::nodes {

LiveDialogueNode::LiveDialogueNode(ros::NodeHandle& nh, const dialogue::DialogueSetup& setup,
                                   const dialogue::RobotNlu& nlu,
                                   const dialogue::DialogueRunConfig& run,
                                   dialogue::SpeechStage& stage)
    : dialogue_(setup, nlu, run, stage), tts_(nh, "/tts", false) {
  utterance_pub_ = nh.advertise<DialogueUtterance>("/sim/dialogue/utterances", 100);
  outcome_pub_ = nh.advertise<DialogueOutcome>("/sim/dialogue/outcome", 10, /*latch=*/true);
  tts_.registerGoalCallback([this] { on_goal(); });
  tts_.registerPreemptCallback([this] { on_preempt(); });
  tts_.start();
}

void LiveDialogueNode::on_goal() {
  const TtsGoalConstPtr goal = tts_.acceptNewGoal();
  TtsResult result;
  try {
    check_tts_goal(*goal);
    result.msg = dialogue_.request_robot(goal->rawtext.text, goal->wait_before_speaking);
  } catch (const core::RequestError& e) {
    // The new goal preempted the one before (actionlib), refused or not: ARI stops there too.
    result.msg = e.what();
    dialogue_.cancel_robot();
  }
  publish(dialogue_.take_events());
  if (!result.msg.empty()) {
    ROS_WARN("/tts goal rejected: %s", result.msg.c_str());
    tts_.setAborted(result, result.msg);
  }
}

void LiveDialogueNode::on_preempt() {
  TtsResult result;
  result.text = dialogue_.cancel_robot();
  result.msg = "cancelled";
  publish(dialogue_.take_events());
  tts_.setPreempted(result);
}

void LiveDialogueNode::tick() {
  const bool was_active = dialogue_.dialogue_active();
  dialogue_.tick();
  if (!was_active && dialogue_.dialogue_active()) {
    ROS_INFO("dialogue: seed %lu, goals: %zu", static_cast<unsigned long>(dialogue_.live().seed()),
             dialogue_.live().env().users().agenda().goals().size());
  }
  const dialogue::SpokenDialogueEvents events = dialogue_.take_events();
  for (const dialogue::RobotWordEvent& word : events.robot_words) {
    TtsFeedback feedback;
    feedback.event_type = TtsFeedback::TTS_EVENT_STARTED_PLAYING_WORD;
    feedback.timestamp = ros::Time(word.since_start_s);
    feedback.text_said = word.text_said;
    tts_.publishFeedback(feedback);
  }
  publish(events);
  if (events.robot_done && tts_.isActive()) {
    TtsResult result;
    result.text = *events.robot_done;
    tts_.setSucceeded(result);
  }
}

void LiveDialogueNode::publish(const dialogue::SpokenDialogueEvents& events) {
  for (const dialogue::UtteranceEvent& event : events.utterances) {
    utterance_pub_.publish(to_msg(dialogue_.live().env().transcript()[event.index], event));
  }
  for (const dialogue::OutcomeEvent& outcome : events.outcomes) {
    outcome_pub_.publish(to_msg(outcome));
    ROS_INFO(
        "dialogue %u ended: complete %d, success %d, truncated %d, %d robot turns, %d "
        "utterances, reward %.0f",
        outcome.dialogue, outcome.complete, outcome.success, outcome.truncated, outcome.robot_turns,
        outcome.utterances, outcome.total_reward);
  }
}

}  // namespace ari_social_sim::nodes
