#pragma once

#include <vector>

namespace ari_social_sim::audio {

/// `samples` at `from_hz` resampled to `to_hz` with a windowed-sinc low-pass at the lower
/// Nyquist frequency (espeak-ng speaks at 22,050 Hz; the array records at 16,000 Hz).
std::vector<float> resample(const std::vector<float>& samples, int from_hz, int to_hz);

}  // namespace ari_social_sim::audio
