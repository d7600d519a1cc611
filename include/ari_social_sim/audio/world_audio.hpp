#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "ari_social_sim/audio/array_mixer.hpp"
#include "ari_social_sim/audio/speech_synthesizer.hpp"
#include "ari_social_sim/model/world_description.hpp"
#include "ari_social_sim/world/speech_generator.hpp"
#include "ari_social_sim/world/world_snapshot.hpp"

namespace ari_social_sim::audio {

/// Samples in one chunk of the audio topics: 1024 at 16 kHz, 64 ms (respeaker_ros reads the
/// array in buffers of 1024 frames).
inline constexpr size_t kChunkSamples = 1024;

/// The world's walls as the acoustics' walls (floor-to-ceiling segments along each wall's length).
std::vector<Wall> walls_of(const model::WorldDescription& world);

/// Where a speaking person's mouth is from ARI's array: the truth a localiser is measured against.
struct SpeakerDirection {
  uint64_t human_id{0};
  double azimuth_rad{0.0};  // counter-clockwise from the array's forward (torso_mic_front_link x)
  double distance_m{0.0};
};

/// The direction of every human speaking in `snapshot`; none without ARI.
std::vector<SpeakerDirection> speaker_directions(const world::WorldSnapshot& snapshot);

/// What ARI's microphone array hears of a world, followed snapshot by snapshot: the same core for
/// the live audio node and the in-process engine, so both produce the same samples for the same
/// run (docs/audio.md).
class WorldAudio {
 public:
  WorldAudio(const RoomSettings& room, std::vector<Wall> walls, uint64_t seed,
             std::shared_ptr<SpeechSynthesizer> synthesizer);

  /// Follows `snapshot`: an utterance begun since the last one is synthesised in its speaker's
  /// voice, fitted to the world's word timing and placed at its start; an utterance cut short
  /// stops; speakers and the array move to where they are now.
  void observe(const world::WorldSnapshot& snapshot);

  /// The whole chunks that end at or before `time_s` and have not been returned yet.
  std::vector<ArrayChunk> chunks_until(double time_s);

  /// Utterances longer than the synthesiser takes, cut at a word (speech_synthesizer.hpp).
  size_t truncated_utterances() const { return truncated_; }
  bool voice_at(int64_t sample) const { return mixer_.voice_at(sample); }

 private:
  struct Utterance {
    double start_s{-1.0};
    std::string content;
  };
  // Stops what `id` no longer says; true when `speech` is an utterance begun since the last
  // snapshot, to be placed (the voice is drawn only then).
  bool starts_utterance(uint64_t id, const world::SpeechSnapshot& speech);
  void place(uint64_t id, const world::SpeechSnapshot& speech, const Voice& voice, bool from_ari);

  ArrayMixer mixer_;
  uint64_t seed_;
  std::shared_ptr<SpeechSynthesizer> synthesizer_;
  std::map<uint64_t, Utterance> placed_;  // each speaker's utterance placed last
  size_t truncated_{0};
};

}  // namespace ari_social_sim::audio
