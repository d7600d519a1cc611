#pragma once

#include <cmath>
#include <memory>
#include <vector>

#include "ari_social_sim/audio/array_mixer.hpp"
#include "ari_social_sim/core/rng.hpp"

namespace ari_social_sim::audio::test {

/// A room with nothing but the direct sound: no reflections, no tail, no noise.
inline RoomSettings anechoic() {
  RoomSettings settings;
  settings.floor_reflection = 0.0;
  settings.wall_reflection = 0.0;
  settings.reverb_level = 0.0;
  settings.noise_level_dbfs = -120.0;
  return settings;
}

/// `seconds` of white noise low-passed to speech's band (a one-pole filter at about 3 kHz).
inline std::shared_ptr<const std::vector<float>> noise_burst(double seconds, uint64_t seed) {
  core::Rng rng(seed);
  auto signal = std::make_shared<std::vector<float>>(static_cast<size_t>(seconds * 16000));
  double smoothed = 0.0;
  for (float& s : *signal) {
    smoothed = 0.7 * smoothed + 0.3 * rng.normal(0.0, 1.0);
    s = static_cast<float>(smoothed);
  }
  return signal;
}

/// The array at the origin, level, facing +x, 0.93 m up (ARI standing at the origin).
inline Eigen::Isometry3d array_at_origin() {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(0.0, 0.0, 0.928);
  return pose;
}

/// Renders `seconds` of the mixer's output as floats per channel.
inline std::array<std::vector<float>, 6> record(ArrayMixer& mixer, double seconds) {
  std::array<std::vector<float>, 6> out;
  const size_t total = static_cast<size_t>(seconds * 16000);
  while (out[0].size() < total) {
    const ArrayChunk chunk = mixer.render(1024);
    for (size_t c = 0; c < 6; ++c) {
      for (const int16_t s : chunk.channels[c]) {
        out[c].push_back(s / 32768.0f);
      }
    }
  }
  return out;
}

inline double rms(const std::vector<float>& signal, size_t from = 0, size_t to = 0) {
  to = to == 0 ? signal.size() : to;
  double sum = 0.0;
  for (size_t i = from; i < to; ++i) {
    sum += double(signal[i]) * signal[i];
  }
  return std::sqrt(sum / std::max<size_t>(to - from, 1));
}

}  // namespace ari_social_sim::audio::test
