#pragma once

#include <string>

namespace ari_social_sim::perception {

/// A final transcript of ARI's speech recognition (ROS4HRI's /humans/voices/<id>/speech `final`):
/// which voice said it, the words, and the recogniser's confidence in [0, 1].
struct VoiceTranscript {
  std::string voice_id;
  std::string text;
  double confidence{1.0};
};

}  // namespace ari_social_sim::perception
