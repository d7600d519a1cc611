#pragma once

#include <Eigen/Core>
#include <vector>

#include "ari_social_sim/core/config_fields.hpp"

namespace ari_social_sim::audio {

/// A wall of the room, floor to ceiling, between two points of the floor plan (world frame).
struct Wall {
  Eigen::Vector2d a{Eigen::Vector2d::Zero()};
  Eigen::Vector2d b{Eigen::Vector2d::Zero()};
};

/// How the room sounds (docs/audio.md, "The room").
struct RoomSettings {
  double rt60_s{0.5};               // reverberation time of the late tail
  double wall_reflection{0.7};      // pressure reflection coefficient of walls (absorption 0.51)
  double floor_reflection{0.5};     // of the floor
  double reverb_level{0.12};        // the late tail's send, relative to the direct sound at 1 m
  double speech_level_dbfs{-26.0};  // a voice's level 1 m away, in dB full scale
  // ARI's voice 1 m from its loudspeaker: set below a person's so that the array, 0.4 m from the
  // loudspeaker, does not clip on it (at -26 dBFS its peaks did).
  double ari_speech_level_dbfs{-34.0};
  double noise_level_dbfs{-65.0};  // the diffuse background noise at every microphone

  template <class V>
  void visit(V& v) {
    v.field("rt60_s", rt60_s, "reverberation time of the late tail (s)", core::Bounds{0.05, 5.0});
    v.field("wall_reflection", wall_reflection, "pressure reflection coefficient of the walls",
            core::Bounds{0.0, 1.0});
    v.field("floor_reflection", floor_reflection, "pressure reflection coefficient of the floor",
            core::Bounds{0.0, 1.0});
    v.field("reverb_level", reverb_level,
            "the late tail's level relative to the direct sound at 1 m", core::Bounds{0.0, 1.0});
    v.field("speech_level_dbfs", speech_level_dbfs, "a voice's RMS level 1 m away (dB full scale)",
            core::Bounds{-80.0, 0.0});
    v.field("ari_speech_level_dbfs", ari_speech_level_dbfs,
            "ARI's voice RMS level 1 m from its loudspeaker (dB full scale); the array is 0.4 m "
            "from it",
            core::Bounds{-80.0, 0.0});
    v.field("noise_level_dbfs", noise_level_dbfs,
            "diffuse background noise at each microphone (dB full scale)",
            core::Bounds{-120.0, 0.0});
  }
};

/// Throws core::ConfigError naming the field and bounds when a setting is out of range.
void check_room_settings(const RoomSettings& settings);

/// One way sound takes from a source to a microphone: its delay and its amplitude gain (1 at
/// 1 m for the direct sound).
struct SoundPath {
  double delay_s{0.0};
  double gain{0.0};
};

/// The speed of sound in air at 20 degrees Celsius.
inline constexpr double kSpeedOfSoundMps = 343.0;

/// The direct path and the first-order image sources (each wall whose mirror point lies on it,
/// and the floor) from `source` to `microphone`, both in the world frame (z up from the floor);
/// spherical spreading (1 / distance) and the reflection coefficients as gains.
std::vector<SoundPath> sound_paths(const Eigen::Vector3d& source, const Eigen::Vector3d& microphone,
                                   const std::vector<Wall>& walls, const RoomSettings& settings);

}  // namespace ari_social_sim::audio
