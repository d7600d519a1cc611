#include "ari_social_sim/audio/speech_recognition_run_config.hpp"

#include "ari_social_sim/core/config_check.hpp"
#include "ari_social_sim/core/config_reader.hpp"

namespace ari_social_sim::audio {

void SpeechRecognitionRunConfig::validate() const {
  core::check_fields(*this, "SpeechRecognitionRunConfig");
}

SpeechRecognitionRunConfig SpeechRecognitionRunConfig::from_yaml(const core::YamlMap& map) {
  return core::read_fields<SpeechRecognitionRunConfig>(map);
}

}  // namespace ari_social_sim::audio
