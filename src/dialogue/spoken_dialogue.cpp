#include "ari_social_sim/dialogue/spoken_dialogue.hpp"

#include <algorithm>
#include <cmath>

#include "ari_social_sim/core/config_check.hpp"
#include "ari_social_sim/dialogue/dialogue_runner.hpp"
#include "ari_social_sim/dialogue/text.hpp"

namespace ari_social_sim::dialogue {

SpokenDialogue::SpokenDialogue(const DialogueSetup& setup, const RobotNlu& nlu,
                               const DialogueRunConfig& run, SpeechStage& stage)
    : setup_(setup), run_(core::validated(run)), stage_(stage), live_(setup, nlu, run.live) {
  next_start_s_ = run.humans ? 0.0 : -1.0;
}

SpokenDialogueEvents SpokenDialogue::take_events() {
  SpokenDialogueEvents taken = std::move(events_);
  events_ = SpokenDialogueEvents{};
  return taken;
}

std::string SpokenDialogue::request_robot(const std::string& text, double wait_before_speaking_s) {
  const double now = stage_.now_s();
  // A new utterance cuts off the one being spoken: ARI said the words started so far.
  if (robot_speaking_) {
    finish_robot(robot_words(stage_.robot_words_started()), now);
  }
  robot_waiting_ = false;
  if (split_words(text).empty()) {
    live_.release_floor();
    return "rawtext.text: expected the words to say, got '" + text + "'";
  }
  if (!std::isfinite(wait_before_speaking_s) || wait_before_speaking_s < 0.0) {
    live_.release_floor();
    return "wait_before_speaking: expected a number >= 0, got " +
           std::to_string(wait_before_speaking_s);
  }
  robot_text_ = text;
  robot_word_list_ = split_words(robot_text_);
  robot_not_before_s_ = now + wait_before_speaking_s;
  robot_waiting_ = true;
  if (dialogue_active_) {
    live_.request_floor();
  }
  return "";
}

std::string SpokenDialogue::cancel_robot() {
  const double now = stage_.now_s();
  std::string said;
  if (robot_speaking_) {
    // The stage cannot unsay words: the world plays the utterance to its end, but the dialogue
    // takes ARI to have said only the words started so far.
    said = robot_words(stage_.robot_words_started());
    finish_robot(said, now);
  } else if (robot_waiting_) {
    robot_waiting_ = false;
    live_.release_floor();
  }
  return said;
}

void SpokenDialogue::tick() {
  const double now = stage_.now_s();
  if (now < last_tick_s_ - kTimeBackToleranceS) {
    restart_clock(now);
  }
  last_tick_s_ = now;
  const bool may_start =
      !dialogue_active_ && next_start_s_ >= 0.0 && now >= next_start_s_ && stage_.has_listener();
  if (may_start && run_.start == DialogueStart::kAtOnce) {
    start_dialogue(now, Opening::kDrawn);
  }
  // ARI: takes the floor when the humans leave it, then speaks its words one by one.
  const bool floor_free = !dialogue_active_ || live_.robot_may_speak();
  if (robot_waiting_ && floor_free && now >= robot_not_before_s_) {
    if (may_start && run_.start == DialogueStart::kRobotSpeaks) {
      start_dialogue(now, Opening::kRobot);
    }
    robot_waiting_ = false;
    robot_speaking_ = true;
    robot_start_s_ = now;
    robot_words_reported_ = 0;
    stage_.start_robot(robot_text_);
  }
  if (robot_speaking_) {
    const size_t started = std::min(stage_.robot_words_started(), robot_word_list_.size());
    for (; robot_words_reported_ < started; ++robot_words_reported_) {
      events_.robot_words.push_back(
          {std::max(0.0, now - robot_start_s_), robot_words(robot_words_reported_ + 1)});
    }
    if (stage_.robot_done()) {
      finish_robot(robot_text_, now);
      events_.robot_done = robot_text_;
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
    const Utterance& u = live_.env().transcript()[static_cast<size_t>(due)];
    const auto& roles = setup_.config.users.roles;
    const size_t human =
        static_cast<size_t>(std::find(roles.begin(), roles.end(), u.speaker) - roles.begin());
    report_utterance(due, now);
    stage_.start_human(u, human);
    human_playing_ = true;
  }
  if (live_.over()) {
    end_dialogue(now, false);
  }
}

void SpokenDialogue::end_dialogue(double now_s, bool cut_off) {
  report_outcome(now_s, cut_off);
  dialogue_active_ = false;
  human_playing_ = false;
  ++dialogue_index_;
  const bool more = run_.dialogues == 0 || dialogue_index_ < run_.dialogues;
  next_start_s_ = more ? now_s + run_.dialogue_pause_s : -1.0;
}

// The stage's clock went back (/sim/reset): every time held is from before it. A dialogue under
// way ends cut off (the reset put its speakers back in their places, silent) and the next starts
// a pause later; ARI's utterance waits what it had left to wait, and one it was speaking counts
// from now.
void SpokenDialogue::restart_clock(double now_s) {
  if (dialogue_active_) {
    end_dialogue(now_s, true);
  } else if (next_start_s_ >= 0.0) {
    next_start_s_ = now_s + std::max(0.0, next_start_s_ - last_tick_s_);
  }
  robot_not_before_s_ = now_s + std::max(0.0, robot_not_before_s_ - last_tick_s_);
  robot_start_s_ = now_s;
}

void SpokenDialogue::start_dialogue(double now_s, Opening opening) {
  live_.start(episode_seed(run_.seed, dialogue_index_), now_s, opening);
  if (robot_waiting_ || robot_speaking_) {
    live_.request_floor();
  }
  dialogue_active_ = true;
  human_playing_ = false;
}

void SpokenDialogue::finish_robot(const std::string& said, double now_s) {
  robot_speaking_ = false;
  if (!dialogue_active_) {
    return;  // ARI spoke outside a dialogue: nobody simulated heard it
  }
  if (said.empty()) {
    live_.release_floor();
    return;
  }
  const int index = live_.robot_finished(said, now_s);
  if (index >= 0) {
    report_utterance(index, robot_start_s_);
  }
}

void SpokenDialogue::report_utterance(int index, double stamp_s) {
  const Utterance& u = live_.env().transcript()[static_cast<size_t>(index)];
  UtteranceEvent event{index, dialogue_index_, stamp_s, stage_.robot_id()};
  if (!u.is_robot()) {
    const auto& roles = setup_.config.users.roles;
    const size_t human =
        static_cast<size_t>(std::find(roles.begin(), roles.end(), u.speaker) - roles.begin());
    event.speaker_id = stage_.human_id(human);
  }
  events_.utterances.push_back(event);
}

void SpokenDialogue::report_outcome(double now_s, bool cut_off) {
  const StepResult& last = live_.last_result();
  events_.outcomes.push_back(
      {dialogue_index_, live_.seed(), now_s, last.info.complete && !cut_off,
       last.info.success && !cut_off, last.truncated || cut_off, last.info.robot_turns,
       static_cast<int>(live_.env().transcript().size()), live_.total_reward(), last.info.goals});
}

std::string SpokenDialogue::robot_words(size_t count) const {
  std::string text;
  for (size_t i = 0; i < count && i < robot_word_list_.size(); ++i) {
    text += (i == 0 ? "" : " ") + robot_word_list_[i];
  }
  return text;
}

}  // namespace ari_social_sim::dialogue
