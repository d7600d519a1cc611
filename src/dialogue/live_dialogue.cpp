#include "ari_social_sim/dialogue/live_dialogue.hpp"

#include "ari_social_sim/core/config_check.hpp"

namespace ari_social_sim::dialogue {

void LiveDialogueConfig::validate() const {
  core::check_fields(*this, "LiveDialogueConfig");
}

LiveDialogue::LiveDialogue(const DialogueSetup& setup, const RobotNlu& nlu,
                           LiveDialogueConfig config)
    : nlu_(nlu), config_(config), env_(setup) {
  config_.validate();
}

void LiveDialogue::start(uint64_t seed, double now_s, Opening opening) {
  seed_ = seed;
  queue_.clear();
  human_playing_ = false;
  robot_wants_floor_ = false;
  last_result_ = StepResult{};
  total_reward_ = 0.0;
  env_.reset(seed, opening);
  // The opening's first utterance starts now; its own gap (from the dialogue's start) is kept.
  last_end_s_ = now_s;
  gap_done_ = false;
  enqueue_humans(0);
}

void LiveDialogue::request_floor() {
  robot_wants_floor_ = true;
}

int LiveDialogue::robot_finished(const std::string& text, double now_s) {
  robot_wants_floor_ = false;
  last_end_s_ = now_s;
  gap_done_ = false;
  if (env_.episode_over()) {
    return -1;
  }
  const size_t robot_index = env_.transcript().size();
  RobotAction action;
  action.acts = nlu_.understand(text);
  action.text = text;
  step(action);
  return static_cast<int>(robot_index);
}

int LiveDialogue::next_due(double now_s) {
  if (human_playing_) {
    return -1;
  }
  if (queue_.empty()) {
    // ARI let the floor go: the humans carry on (an RL step with a silent robot).
    if (robot_wants_floor_ || env_.episode_over() ||
        now_s < last_end_s_ + config_.robot_silence_s) {
      return -1;
    }
    step(RobotAction{});
    gap_done_ = true;
    if (queue_.empty()) {
      return -1;
    }
  }
  const std::vector<Utterance>& transcript = env_.transcript();
  const size_t index = queue_.front();
  const Utterance& u = transcript[index];
  const double gap = index == 0 ? u.start_s : u.start_s - transcript[index - 1].end_s;
  if (!gap_done_ && now_s < last_end_s_ + gap) {
    return -1;
  }
  queue_.pop_front();
  human_playing_ = true;
  gap_done_ = false;
  return static_cast<int>(index);
}

void LiveDialogue::human_finished(double now_s) {
  human_playing_ = false;
  last_end_s_ = now_s;
}

void LiveDialogue::step(const RobotAction& action) {
  const size_t first_new = env_.transcript().size();
  last_result_ = env_.step(action);
  total_reward_ += last_result_.reward;
  enqueue_humans(first_new);
}

void LiveDialogue::enqueue_humans(size_t from) {
  const std::vector<Utterance>& transcript = env_.transcript();
  for (size_t i = from; i < transcript.size(); ++i) {
    if (!transcript[i].is_robot()) {
      queue_.push_back(i);
    }
  }
}

}  // namespace ari_social_sim::dialogue
