#pragma once

#include <cstddef>
#include <vector>

namespace ari_social_sim::audio {

/// `samples` made `length` samples long without changing their pitch, by WSOLA (waveform-similarity
/// overlap-add: 20 ms Hann frames at 16 kHz, each taken within +-5 ms of its nominal place where
/// it best continues the previous one).
std::vector<float> stretch_to(const std::vector<float>& samples, size_t length);

}  // namespace ari_social_sim::audio
