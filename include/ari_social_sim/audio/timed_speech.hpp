#pragma once

#include <vector>

#include "ari_social_sim/audio/speech_synthesizer.hpp"

namespace ari_social_sim::audio {

/// When the world says the words of an utterance: word k at k * 60 / words_per_minute seconds
/// after its start (world::SpeechGenerator's schedule).
std::vector<double> word_onsets_s(size_t word_count, double words_per_minute);

/// `synthesis` fitted to the world's schedule: each word's audio moved so that its energy onset
/// (its first 10 ms at a tenth of the utterance's loudest, after at most 60 ms of softer attack)
/// falls exactly on its onset (relative to the utterance start, at kSampleRateHz) and
/// stretched in time, pitch kept, to fill the time until the next word (squeezed or drawn out by
/// at most 1.6; beyond, cut with a 5 ms fade or followed by silence), so that what is heard and
/// the world's word events agree. The voice spoke at the world's rate, so the stretches are
/// small on average (docs/audio.md, "Voices").
std::vector<float> fit_to_onsets(const Synthesis& synthesis, const std::vector<double>& onsets_s);

}  // namespace ari_social_sim::audio
