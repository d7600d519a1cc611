#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace ari_social_sim::audio {

/// The reverberant tail of a room at one microphone: a feedback delay network (four delay lines
/// mixed by a Householder matrix) whose loop gains make the tail decay by 60 dB in rt60_s. Each
/// microphone has its own delay lengths, so the tails at the four microphones are uncorrelated
/// as a diffuse field's are. Stateful: process the signal in order, chunk after chunk.
class LateReverb {
 public:
  LateReverb(double rt60_s, int sample_rate_hz, size_t microphone);

  /// Adds to `out` the tail excited by `in` (the same length), times `level`.
  void process(const std::vector<float>& in, float level, std::vector<float>& out);

 private:
  std::array<std::vector<float>, 4> lines_;
  std::array<size_t, 4> positions_{};
  std::array<float, 4> gains_{};
};

}  // namespace ari_social_sim::audio
