#include "ari_social_sim/audio/late_reverb.hpp"

#include <cmath>

namespace ari_social_sim::audio {
namespace {

// Mutually prime delay lengths (samples at 16 kHz, 36-115 ms), shifted per microphone.
constexpr std::array<size_t, 4> kBaseDelays{577, 863, 1327, 1847};
constexpr std::array<size_t, 4> kMicrophoneShifts{0, 37, 71, 113};

}  // namespace

LateReverb::LateReverb(double rt60_s, int sample_rate_hz, size_t microphone) {
  for (size_t i = 0; i < lines_.size(); ++i) {
    const size_t delay = (kBaseDelays[i] + kMicrophoneShifts[microphone % 4] * (i + 1)) *
                         static_cast<size_t>(sample_rate_hz) / 16000;
    lines_[i].assign(delay, 0.0f);
    // -60 dB after rt60_s: each pass through a line of `delay` samples loses its share.
    gains_[i] = static_cast<float>(std::pow(10.0, -3.0 * delay / (rt60_s * sample_rate_hz)));
  }
}

void LateReverb::process(const std::vector<float>& in, float level, std::vector<float>& out) {
  for (size_t n = 0; n < in.size(); ++n) {
    std::array<float, 4> taps{};
    float sum = 0.0f;
    for (size_t i = 0; i < 4; ++i) {
      taps[i] = lines_[i][positions_[i]] * gains_[i];
      sum += taps[i];
    }
    out[n] += level * sum * 0.5f;
    // Householder feedback: each line gets the input minus half the sum of all taps, plus its own.
    for (size_t i = 0; i < 4; ++i) {
      lines_[i][positions_[i]] = in[n] + taps[i] - 0.5f * sum;
      positions_[i] = (positions_[i] + 1) % lines_[i].size();
    }
  }
}

}  // namespace ari_social_sim::audio
