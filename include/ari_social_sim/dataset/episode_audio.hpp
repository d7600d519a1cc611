#pragma once

#include <cstdint>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "ari_social_sim/audio/world_audio.hpp"
#include "ari_social_sim/scenario/transcript.hpp"
#include "ari_social_sim/world/scene.hpp"

struct sf_private_tag;  // libsndfile's SNDFILE

namespace ari_social_sim::dataset {

/// Who speaks when, in NIST's RTTM: one SPEAKER line per utterance of `lines` (finished or cut
/// off by `end_s`), times in seconds of `recording`'s audio (sim time), the speaker named as the
/// transcript names them (spaces replaced by `_`).
std::string rttm_of(const std::vector<scenario::TranscriptLine>& lines,
                    const std::string& recording, double end_s);

/// Every word's timing, in NIST's CTM: `recording 1 start duration word`, a word at the world's
/// word time (start + k * 60 / words_per_minute) lasting until the next word or the utterance's
/// end, whichever is first; words not reached before an utterance was cut off are left out.
std::string ctm_of(const std::vector<scenario::TranscriptLine>& lines, const std::string& recording,
                   double end_s);

/// One episode's audio as a data set (docs/audio.md, "Audio data sets"), from the world's
/// snapshots as the episode runs: STEM.wav (the array's six channels, 16 kHz 16-bit, the live
/// audio_node's samples), STEM.rttm and STEM.ctm (who speaks when and every word, the world's
/// own times), and STEM_directions.csv (per 64 ms chunk, each speaking person's true direction
/// and distance from the array). Throws core::Error naming the file when one cannot be written.
class EpisodeAudio {
 public:
  EpisodeAudio(const std::string& stem, const world::Scene& scene, uint64_t seed,
               const audio::RoomSettings& room,
               std::shared_ptr<audio::SpeechSynthesizer> synthesizer);
  ~EpisodeAudio();
  EpisodeAudio(const EpisodeAudio&) = delete;
  EpisodeAudio& operator=(const EpisodeAudio&) = delete;

  void observe(const world::WorldSnapshot& snapshot);
  /// Writes the labels and closes the files, the audio up to the last snapshot's time.
  void finish();

  /// The stem of episode `seed` of scenario `name` in a batch tool's output `dir`:
  /// DIR/audio/NAME_SEED.
  static std::string stem_of(const std::string& dir, const std::string& name, uint64_t seed);
  /// The files this writes, STEM.wav first.
  static std::vector<std::string> files_of(const std::string& stem);

 private:
  void write(const audio::ArrayChunk& chunk, const world::WorldSnapshot& snapshot);

  std::string stem_;
  std::string recording_;  // the stem's file name, the recording's id in the labels
  audio::WorldAudio audio_;
  scenario::Transcript transcript_;
  sf_private_tag* wav_{nullptr};
  std::ofstream directions_;
  double last_time_s_{0.0};
  std::vector<int16_t> interleaved_;
};

}  // namespace ari_social_sim::dataset
