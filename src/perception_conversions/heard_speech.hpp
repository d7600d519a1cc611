#pragma once

#include <ros/ros.h>

#include <map>
#include <string>
#include <vector>

#include "ari_social_sim/IdsList.h"
#include "ari_social_sim/LiveSpeech.h"
#include "ari_social_sim/perception/voice_transcript.hpp"

namespace ari_social_sim::nodes {

/// What ROS4HRI speech recognition heard, for a node that acts on it (scenario_node): follows
/// /humans/voices/tracked and each tracked voice's /humans/voices/<id>/speech, and keeps their
/// final transcripts until taken. Whatever publishes the voices (hri_perception_node's simulated
/// recogniser, speech_recognition_node on the array's audio, a real ASR) is heard the same way. A
/// voice out of the tracked list for `forget_after_s` of wall time is dropped with its
/// subscription. Captures `this` in callbacks: not copyable or movable.
class HeardSpeech {
 public:
  explicit HeardSpeech(const ros::NodeHandle& nh, double forget_after_s = 10.0);
  HeardSpeech(const HeardSpeech&) = delete;
  HeardSpeech& operator=(const HeardSpeech&) = delete;

  /// The final transcripts that arrived since the last call, in order.
  std::vector<perception::VoiceTranscript> take();

 private:
  struct Followed {
    ros::Subscriber speech_sub;
    double last_tracked_s{0.0};
  };
  void on_tracked(const IdsList& msg);
  void on_speech(const std::string& voice_id, const LiveSpeech& msg);

  ros::NodeHandle nh_;
  double forget_after_s_;
  ros::Subscriber tracked_sub_;
  std::map<std::string, Followed> followed_;
  std::vector<perception::VoiceTranscript> finals_;
};

}  // namespace ari_social_sim::nodes
