#pragma once

#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <vector>

#include "ari_social_sim/audio/late_reverb.hpp"
#include "ari_social_sim/audio/room_acoustics.hpp"
#include "ari_social_sim/core/rng.hpp"
#include "ari_social_sim/model/ari_sensor_geometry.hpp"

namespace ari_social_sim::audio {

inline constexpr size_t kMicrophones = 4;

/// A sound in the room: a speaker's fitted utterance from its start sample on.
struct PlacedSound {
  uint64_t source{0};  // who speaks: a world id; ARI's sounds come from ARI
  std::shared_ptr<const std::vector<float>> signal;
  int64_t start_sample{0};
  bool from_ari{false};
};

/// What the array records over a span of samples: the six channels of ReSpeaker's firmware.
struct ArrayChunk {
  int64_t first_sample{0};
  std::array<std::vector<int16_t>, model::kArrayChannels> channels;
};

/// Every voice in the room as ARI's microphone array hears it, sample by sample in sim time:
/// each sound reaches each microphone over its direct path, floor and wall reflections
/// (room_acoustics), a late reverberant tail (LateReverb) and diffuse noise are added, and the
/// channels are formed as the array's firmware forms them (docs/audio.md, "The array"):
/// 0 processed (the four microphones averaged, ARI's own voice removed as by ideal echo
/// cancellation), 1-4 the raw microphones, 5 the playback (ARI's voice as played).
/// Deterministic: the same sounds, positions and seed give the same samples, whatever the chunk
/// sizes.
class ArrayMixer {
 public:
  ArrayMixer(const RoomSettings& settings, std::vector<Wall> walls, uint64_t seed);

  void add(PlacedSound sound);
  /// `source` stops speaking at `sample`: what it still had to say is not heard.
  void stop_source(uint64_t source, int64_t sample);
  /// Where each source is now (world frame, mouth height) and where the array is.
  void set_source_position(uint64_t source, const Eigen::Vector3d& position);
  void set_array_pose(const Eigen::Isometry3d& X_world_array);

  /// The next `count` samples (each call continues where the last one ended); sounds that have
  /// ended are dropped.
  ArrayChunk render(size_t count);

  int64_t next_sample() const { return next_sample_; }
  size_t active_sounds() const { return sounds_.size(); }
  /// Whether any sound other than ARI's plays at `sample`.
  bool voice_at(int64_t sample) const;

 private:
  void add_sound(const PlacedSound& sound, size_t count,
                 std::array<std::vector<float>, kMicrophones>& raw,
                 std::vector<float>& playback) const;
  void add_noise(std::array<std::vector<float>, kMicrophones>& raw, std::vector<float>& processed);
  void drop_ended_sounds();

  RoomSettings settings_;
  std::vector<Wall> walls_;
  core::Rng noise_;
  std::vector<PlacedSound> sounds_;
  std::map<uint64_t, Eigen::Vector3d> positions_;
  Eigen::Isometry3d X_world_array_{Eigen::Isometry3d::Identity()};
  std::vector<LateReverb> reverbs_;
  int64_t next_sample_{0};
};

}  // namespace ari_social_sim::audio
