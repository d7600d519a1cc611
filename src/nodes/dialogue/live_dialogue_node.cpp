#include "dialogue/live_dialogue_node.hpp"

#include <cmath>

#include "ari_social_sim/DialogueOutcome.h"
#include "ari_social_sim/DialogueUtterance.h"
#include "ari_social_sim/dialogue/dialogue_runner.hpp"
#include "ari_social_sim/dialogue/text.hpp"
#include "conversions/dialogue.hpp"

namespace ari_social_sim::nodes {

LiveDialogueNode::LiveDialogueNode(ros::NodeHandle& nh, const dialogue::DialogueSetup& setup,
                                   const dialogue::RobotNlu& nlu,
                                   const dialogue::DialogueRunConfig& run, SpeechStage& stage)
    : setup_(setup),
      run_(run),
      stage_(stage),
      live_(setup, nlu, run.live),
      next_start_s_(0.0),
      tts_(nh, "/tts", false) {
  utterance_pub_ = nh.advertise<DialogueUtterance>("/sim/dialogue/utterances", 100);
  outcome_pub_ = nh.advertise<DialogueOutcome>("/sim/dialogue/outcome", 10, /*latch=*/true);
  tts_.registerGoalCallback([this] { on_goal(); });
  tts_.registerPreemptCallback([this] { on_preempt(); });
  tts_.start();
}

void LiveDialogueNode::on_goal() {
  const double now = stage_.now_s();
  // A new goal preempts the one being spoken (actionlib's simple server): ARI is cut off there.
  if (robot_speaking_) {
    finish_robot(robot_words(stage_.robot_words_started()), now);
  }
  robot_waiting_ = false;
  const TtsGoalConstPtr goal = tts_.acceptNewGoal();
  TtsResult result;
  if (goal->rawtext.text.empty() || dialogue::split_words(goal->rawtext.text).empty()) {
    result.msg = goal->text.key.empty()
                     ? "rawtext.text: expected the words to say, got ''"
                     : "text: I18nText lookup (section/key) is not simulated; fill rawtext.text";
  } else if (!std::isfinite(goal->wait_before_speaking) || goal->wait_before_speaking < 0.0) {
    result.msg = "wait_before_speaking: expected a number >= 0, got " +
                 std::to_string(goal->wait_before_speaking);
  }
  if (!result.msg.empty()) {
    ROS_WARN("/tts goal rejected: %s", result.msg.c_str());
    live_.release_floor();
    tts_.setAborted(result, result.msg);
    return;
  }
  robot_text_ = goal->rawtext.text;
  robot_word_list_ = dialogue::split_words(robot_text_);
  robot_not_before_s_ = now + goal->wait_before_speaking;
  robot_waiting_ = true;
  live_.request_floor();
}

void LiveDialogueNode::on_preempt() {
  const double now = stage_.now_s();
  TtsResult result;
  if (robot_speaking_) {
    // The stage cannot unsay words: the world plays the utterance to its end, but the dialogue
    // takes ARI to have said only the words started so far.
    result.text = robot_words(stage_.robot_words_started());
    finish_robot(result.text, now);
  } else if (robot_waiting_) {
    robot_waiting_ = false;
    live_.release_floor();
  }
  result.msg = "cancelled";
  tts_.setPreempted(result);
}

void LiveDialogueNode::tick() {
  const double now = stage_.now_s();
  if (!dialogue_active_ && next_start_s_ >= 0.0 && now >= next_start_s_ && stage_.has_listener()) {
    start_dialogue(now);
  }
  // ARI: takes the floor when the humans leave it, then speaks its words one by one.
  if (robot_waiting_ && live_.robot_may_speak() && now >= robot_not_before_s_) {
    robot_waiting_ = false;
    robot_speaking_ = true;
    robot_start_s_ = now;
    robot_words_reported_ = 0;
    stage_.start_robot(robot_text_);
  }
  if (robot_speaking_) {
    const size_t started = std::min(stage_.robot_words_started(), robot_word_list_.size());
    for (; robot_words_reported_ < started; ++robot_words_reported_) {
      TtsFeedback feedback;
      feedback.event_type = TtsFeedback::TTS_EVENT_STARTED_PLAYING_WORD;
      feedback.timestamp = ros::Time(std::max(0.0, now - robot_start_s_));
      feedback.text_said = robot_words(robot_words_reported_ + 1);
      tts_.publishFeedback(feedback);
    }
    if (stage_.robot_done()) {
      finish_robot(robot_text_, now);
      TtsResult result;
      result.text = robot_text_;
      tts_.setSucceeded(result);
    }
  }
  if (!dialogue_active_) {
    return;
  }
  // The humans: one utterance at a time, each when the LiveDialogue says it is due.
  if (human_playing_ && stage_.human_done()) {
    human_playing_ = false;
    live_.human_finished(now);
  }
  const int due = live_.next_due(now);
  if (due >= 0) {
    const dialogue::Utterance& u = live_.env().transcript()[static_cast<size_t>(due)];
    const auto& roles = setup_.config.users.roles;
    const size_t human =
        static_cast<size_t>(std::find(roles.begin(), roles.end(), u.speaker) - roles.begin());
    publish_utterance(due, now);
    stage_.start_human(u, human);
    human_playing_ = true;
  }
  if (live_.over()) {
    publish_outcome(now);
    dialogue_active_ = false;
    ++dialogue_index_;
    const bool more = run_.dialogues == 0 || dialogue_index_ < run_.dialogues;
    next_start_s_ = more ? now + run_.dialogue_pause_s : -1.0;
  }
}

void LiveDialogueNode::start_dialogue(double now_s) {
  const uint64_t seed = dialogue::episode_seed(run_.seed, dialogue_index_);
  live_.start(seed, now_s);
  if (robot_waiting_ || robot_speaking_) {
    live_.request_floor();
  }
  dialogue_active_ = true;
  human_playing_ = false;
  ROS_INFO("dialogue %u: seed %lu, goals: %zu", dialogue_index_, static_cast<unsigned long>(seed),
           live_.env().users().agenda().goals().size());
}

void LiveDialogueNode::finish_robot(const std::string& said, double now_s) {
  robot_speaking_ = false;
  if (said.empty()) {
    live_.release_floor();
    return;
  }
  const int index = live_.robot_finished(said, now_s);
  if (index >= 0 && dialogue_active_) {
    publish_utterance(index, robot_start_s_);
  }
}

void LiveDialogueNode::publish_utterance(int index, double stamp_s) {
  const dialogue::Utterance& u = live_.env().transcript()[static_cast<size_t>(index)];
  DialogueUtterance msg = to_msg(u, dialogue_index_, stamp_s);
  if (u.is_robot()) {
    msg.speaker_id = stage_.robot_id();
  } else {
    const auto& roles = setup_.config.users.roles;
    const size_t human =
        static_cast<size_t>(std::find(roles.begin(), roles.end(), u.speaker) - roles.begin());
    msg.speaker_id = stage_.human_id(human);
    msg.person_id = person_id(msg.speaker_id);
  }
  utterance_pub_.publish(msg);
}

void LiveDialogueNode::publish_outcome(double now_s) {
  const dialogue::StepResult& last = live_.last_result();
  DialogueOutcome msg;
  msg.header.stamp = ros::Time(now_s);
  msg.dialogue = dialogue_index_;
  msg.seed = live_.seed();
  msg.complete = last.info.complete;
  msg.success = last.info.success;
  msg.truncated = last.truncated;
  msg.robot_turns = last.info.robot_turns;
  msg.utterances = static_cast<int32_t>(live_.env().transcript().size());
  msg.total_reward = live_.total_reward();
  msg.goals = last.info.goals;
  outcome_pub_.publish(msg);
  ROS_INFO(
      "dialogue %u ended: complete %d, success %d, truncated %d, %d robot turns, %d "
      "utterances, reward %.0f",
      dialogue_index_, msg.complete, msg.success, msg.truncated, msg.robot_turns, msg.utterances,
      msg.total_reward);
}

std::string LiveDialogueNode::robot_words(size_t count) const {
  std::string text;
  for (size_t i = 0; i < count && i < robot_word_list_.size(); ++i) {
    text += (i == 0 ? "" : " ") + robot_word_list_[i];
  }
  return text;
}

}  // namespace ari_social_sim::nodes
