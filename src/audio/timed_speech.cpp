#include "ari_social_sim/audio/timed_speech.hpp"

#include <algorithm>
#include <cmath>

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

// Copies samples [from, to) of `source` to `out` at `at`, at most `room` of them, fading out the
// last kFadeSamples when the copy is cut short.
void place(const std::vector<float>& source, size_t from, size_t to, size_t at, size_t room,
           std::vector<float>& out) {
  const size_t length = std::min(to - from, room);
  const bool cut = length < to - from;
  out.resize(std::max(out.size(), at + length), 0.0f);
  for (size_t i = 0; i < length; ++i) {
    float gain = 1.0f;
    if (cut && length - i <= kFadeSamples) {
      gain = static_cast<float>(length - i) / kFadeSamples;
    }
    out[at + i] = source[from + i] * gain;
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
