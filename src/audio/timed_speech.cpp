#include "ari_social_sim/audio/timed_speech.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "ari_social_sim/audio/time_stretch.hpp"

namespace ari_social_sim::audio {
namespace {

constexpr size_t kFadeSamples = kSampleRateHz * 5 / 1000;
// A word's segment starts where espeak-ng's word event is, often before a pause (after a comma,
// before a stop consonant's closure). The word is heard from its energy onset: the first 10 ms
// whose RMS reaches a tenth (-20 dB) of the utterance's loudest 10 ms. It is placed so that this
// onset falls on the world's word time, its softer attack (at most 60 ms: an /h/, an /f/ or a
// /s/ before the vowel, which a recogniser needs) just before it.
constexpr size_t kWindow = kSampleRateHz / 100;
constexpr size_t kLeadIn = kSampleRateHz * 60 / 1000;
constexpr double kOnsetShare = 0.1;

// RMS of the kWindow samples from each index (shorter at the end).
std::vector<double> window_rms(const std::vector<float>& samples) {
  std::vector<double> prefix(samples.size() + 1, 0.0);
  for (size_t i = 0; i < samples.size(); ++i) {
    prefix[i + 1] = prefix[i] + double(samples[i]) * samples[i];
  }
  std::vector<double> rms(samples.size());
  for (size_t i = 0; i < samples.size(); ++i) {
    const size_t end = std::min(samples.size(), i + kWindow);
    rms[i] = std::sqrt((prefix[end] - prefix[i]) / kWindow);
  }
  return rms;
}

// The energy onset in [from, to), or `from` when the word never gets that loud.
size_t energy_onset(const std::vector<double>& rms, size_t from, size_t to, double threshold) {
  for (size_t i = from; i < to; ++i) {
    if (rms[i] >= threshold) {
      return i;
    }
  }
  return from;
}

// The most a word is squeezed or drawn out to fill its slot; beyond, it is cut (with a fade) or
// followed by silence.
constexpr double kMaxStretch = 1.6;

// Samples [from, to) of `source` fitted into `room` samples of `out` at `at`: stretched in time
// (pitch kept) to fill the room, within kMaxStretch, then cut with a fade if still too long.
void place(const std::vector<float>& source, size_t from, size_t to, size_t at, size_t room,
           std::vector<float>& out) {
  const std::vector<float> word(source.begin() + static_cast<std::ptrdiff_t>(from),
                                source.begin() + static_cast<std::ptrdiff_t>(to));
  const double natural = static_cast<double>(word.size());
  const size_t target = static_cast<size_t>(
      std::clamp(static_cast<double>(room), natural / kMaxStretch, natural * kMaxStretch));
  std::vector<float> fitted = stretch_to(word, target);
  const size_t length = std::min(fitted.size(), room);
  out.resize(std::max(out.size(), at + length), 0.0f);
  for (size_t i = 0; i < length; ++i) {
    const bool fading = length < fitted.size() && length - i <= kFadeSamples;
    out[at + i] = fitted[i] * (fading ? static_cast<float>(length - i) / kFadeSamples : 1.0f);
  }
}

}  // namespace

std::vector<double> word_onsets_s(size_t word_count, double words_per_minute) {
  std::vector<double> onsets(word_count);
  for (size_t k = 0; k < word_count; ++k) {
    onsets[k] = static_cast<double>(k) * 60.0 / words_per_minute;
  }
  return onsets;
}

std::vector<float> fit_to_onsets(const Synthesis& synthesis, const std::vector<double>& onsets_s) {
  const std::vector<double> rms = window_rms(synthesis.samples);
  const double loudest = rms.empty() ? 0.0 : *std::max_element(rms.begin(), rms.end());
  const size_t words = std::min(synthesis.word_starts.size(), onsets_s.size());
  // Where each word's audio begins (its attack) and ends in the synthesis, and where it goes.
  struct Span {
    size_t from, to, at;
  };
  std::vector<Span> spans;
  for (size_t k = 0; k < words; ++k) {
    const size_t to = std::min(k + 1 < synthesis.word_starts.size() ? synthesis.word_starts[k + 1]
                                                                    : synthesis.samples.size(),
                               synthesis.samples.size());
    const size_t word_start = std::min(synthesis.word_starts[k], to);
    const size_t onset = energy_onset(rms, word_start, to, kOnsetShare * loudest);
    const size_t slot = static_cast<size_t>(std::lround(onsets_s[k] * kSampleRateHz));
    const size_t lead = std::min({kLeadIn, onset - word_start, slot});
    spans.push_back({onset - lead, to, slot - lead});
  }
  std::vector<float> out;
  for (size_t k = 0; k < spans.size(); ++k) {
    const Span& word = spans[k];
    // Each word fills the time until the next one's attack begins.
    const size_t next = k + 1 < spans.size() ? spans[k + 1].at : word.at + (word.to - word.from);
    if (word.from < word.to && next > word.at) {
      place(synthesis.samples, word.from, word.to, word.at, next - word.at, out);
    }
  }
  return out;
}

}  // namespace ari_social_sim::audio
