#pragma once

#include <array>
#include <vector>

#include "ari_social_sim/audio/array_mixer.hpp"
#include "ari_social_sim/audio/room_acoustics.hpp"

namespace ari_social_sim::audio {

/// How far above the room's noise (dB) the processed channel must be for a chunk to be voice:
/// the array's own detector decides on the signal, not on who the world says is talking.
inline constexpr double kVoiceAboveNoiseDb = 12.0;

/// Whether `chunk` holds voice: its processed channel's RMS kVoiceAboveNoiseDb above the noise.
bool voice_in(const ArrayChunk& chunk, const RoomSettings& room);

/// The four raw microphones of `chunk` (channels 1-4) in [-1, 1], as the localiser takes them.
std::array<std::vector<float>, 4> raw_microphones(const ArrayChunk& chunk);

}  // namespace ari_social_sim::audio
