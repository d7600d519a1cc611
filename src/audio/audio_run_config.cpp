#include "ari_social_sim/audio/audio_run_config.hpp"

#include "ari_social_sim/core/config_check.hpp"
#include "ari_social_sim/core/config_reader.hpp"

namespace ari_social_sim::audio {

void AudioRunConfig::validate() const {
  core::check_fields(*this, "AudioRunConfig");
}

AudioRunConfig AudioRunConfig::from_yaml(const core::YamlMap& map) {
  return core::read_fields<AudioRunConfig>(map);
}

}  // namespace ari_social_sim::audio
