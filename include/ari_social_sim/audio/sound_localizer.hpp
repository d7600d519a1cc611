#pragma once

#include <array>
#include <optional>
#include <vector>

namespace ari_social_sim::audio {

/// Where a sound comes from, in the array's frame (torso_mic_front_link: x forward, y left).
struct SoundDirection {
  double azimuth_rad{0.0};  // counter-clockwise from x, in (-pi, pi]
  double coherence{0.0};    // the steered power at the peak over its most (all pairs and
                            // frequencies in phase): 1 for one source in free field
};

/// The direction of the loudest source in one frame of the four raw microphones (the same length,
/// a power of two), by SRP-PHAT: the phase-transform cross-spectra of the six microphone pairs,
/// steered over azimuths in 1 degree steps for a far source in the array's plane. Nothing when the
/// frame is silent.
std::optional<SoundDirection> locate_sound(const std::array<std::vector<float>, 4>& microphones);

}  // namespace ari_social_sim::audio
