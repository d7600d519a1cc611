#include "ari_social_sim/audio/timed_speech.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "ari_social_sim/audio/time_stretch.hpp"

namespace ari_social_sim::audio {
namespace {

constexpr size_t kFadeSamples = kSampleRateHz * 5 / 1000;
// A word's segment starts where espeak-ng's word event is, often before a pause (after a comma,
// before a stop consonant's closure); the word is heard from its first sample above this share
// of the utterance's peak (-40 dB).
constexpr float kAudibleShare = 0.01f;

// The first sample of [from, to) at least kAudibleShare of `peak`, or `from` if there is none.
size_t audible_from(const std::vector<float>& samples, size_t from, size_t to, float peak) {
  for (size_t i = from; i < to; ++i) {
    if (std::abs(samples[i]) >= kAudibleShare * peak) {
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
  std::vector<float> out;
  float peak = 0.0f;
  for (const float s : synthesis.samples) {
    peak = std::max(peak, std::abs(s));
  }
  const size_t words = std::min(synthesis.word_starts.size(), onsets_s.size());
  for (size_t k = 0; k < words; ++k) {
    const size_t to = k + 1 < synthesis.word_starts.size() ? synthesis.word_starts[k + 1]
                                                           : synthesis.samples.size();
    const size_t from = audible_from(synthesis.samples, synthesis.word_starts[k],
                                     std::min(to, synthesis.samples.size()), peak);
    const size_t at = static_cast<size_t>(std::lround(onsets_s[k] * kSampleRateHz));
    const size_t next = k + 1 < words
                            ? static_cast<size_t>(std::lround(onsets_s[k + 1] * kSampleRateHz))
                            : at + (to - from);
    if (from < to && to <= synthesis.samples.size()) {
      place(synthesis.samples, from, to, at, next - at, out);
    }
  }
  return out;
}

}  // namespace ari_social_sim::audio
