#include "ari_social_sim/audio/chunk_analysis.hpp"

#include <algorithm>
#include <cmath>

namespace ari_social_sim::audio {

bool voice_in(const ArrayChunk& chunk, const RoomSettings& room) {
  const std::vector<int16_t>& processed = chunk.channels[0];
  double sum = 0.0;
  for (const int16_t s : processed) {
    sum += double(s) * s;
  }
  const double mean_square =
      sum / static_cast<double>(std::max<size_t>(processed.size(), 1)) / (32768.0 * 32768.0);
  return 10.0 * std::log10(mean_square + 1e-20) > room.noise_level_dbfs + kVoiceAboveNoiseDb;
}

std::array<std::vector<float>, 4> raw_microphones(const ArrayChunk& chunk) {
  std::array<std::vector<float>, 4> microphones;
  for (size_t m = 0; m < microphones.size(); ++m) {
    for (const int16_t s : chunk.channels[1 + m]) {
      microphones[m].push_back(s / 32768.0f);
    }
  }
  return microphones;
}

}  // namespace ari_social_sim::audio
