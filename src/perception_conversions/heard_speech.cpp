#include "heard_speech.hpp"

#include "node_support/per_id_handle.hpp"

namespace ari_social_sim::nodes {

HeardSpeech::HeardSpeech(const ros::NodeHandle& nh, double forget_after_s)
    : nh_(nh), forget_after_s_(forget_after_s) {
  tracked_sub_ = nh_.subscribe("/humans/voices/tracked", 10, &HeardSpeech::on_tracked, this);
}

std::vector<perception::VoiceTranscript> HeardSpeech::take() {
  std::vector<perception::VoiceTranscript> finals;
  finals.swap(finals_);
  return finals;
}

void HeardSpeech::on_tracked(const IdsList& msg) {
  const double now_s = ros::WallTime::now().toSec();
  for (const std::string& id : msg.ids) {
    Followed& followed = followed_[id];
    followed.last_tracked_s = now_s;
    if (!followed.speech_sub) {
      ros::NodeHandle handle = per_id_handle(nh_);
      followed.speech_sub = handle.subscribe<LiveSpeech>(
          "/humans/voices/" + id + "/speech", 10,
          [this, id](const LiveSpeech::ConstPtr& msg) { on_speech(id, *msg); });
    }
  }
  for (auto it = followed_.begin(); it != followed_.end();) {
    it = now_s - it->second.last_tracked_s > forget_after_s_ ? followed_.erase(it) : std::next(it);
  }
}

void HeardSpeech::on_speech(const std::string& voice_id, const LiveSpeech& msg) {
  if (!msg.final.empty()) {
    finals_.push_back({voice_id, msg.final, msg.confidence});
  }
}

}  // namespace ari_social_sim::nodes
