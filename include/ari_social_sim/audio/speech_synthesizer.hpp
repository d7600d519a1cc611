#pragma once

#include <cstddef>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "ari_social_sim/audio/voice.hpp"
#include "ari_social_sim/model/ari_sensor_geometry.hpp"

namespace ari_social_sim::audio {

/// The synthesis' sample rate: the array's.
inline constexpr int kSampleRateHz = model::kArraySampleRateHz;
/// Longest text synthesised, in bytes; a longer utterance is cut at the last word boundary before
/// it (about a minute of speech), and the cut is reported (docs/audio.md, "Bad input").
inline constexpr size_t kMaxUtteranceBytes = 1000;

/// One utterance as espeak-ng spoke it, at kSampleRateHz, with where each word starts.
struct Synthesis {
  std::vector<float> samples;       // mono, full scale +-1
  std::vector<size_t> word_starts;  // sample index of each word's start, in text order
  bool truncated{false};            // the text was longer than kMaxUtteranceBytes
};

/// Text to speech with libespeak-ng, cached per (voice, text).
///
/// espeak-ng carries state from one utterance to the next (the same text sounds slightly
/// different after another one), so each synthesis runs in a child process that starts from the
/// library's initial state: the same voice and text give the same samples in every run, whatever
/// was said before. A synthesis costs about 20 ms; the cache makes repeats free.
class SpeechSynthesizer {
 public:
  /// Throws core::RequestError for control characters in `text` or an invalid voice; an empty
  /// text gives an empty synthesis.
  std::shared_ptr<const Synthesis> synthesize(const std::string& text, const Voice& voice);

  size_t cached() const;

 private:
  mutable std::mutex mutex_;
  std::map<std::string, std::shared_ptr<const Synthesis>> cache_;
};

/// `text` without what espeak-ng would misread: throws core::RequestError for a control character
/// (tab and newline excepted), and cuts at the last word boundary before kMaxUtteranceBytes.
std::string speakable_text(const std::string& text, bool* truncated);

}  // namespace ari_social_sim::audio
