#pragma once

#include <vector>

#include "ari_social_sim/audio/speech_synthesizer.hpp"

namespace ari_social_sim::audio {

/// When the world says the words of an utterance: word k at k * 60 / words_per_minute seconds
/// after its start (world::SpeechGenerator's schedule).
std::vector<double> word_onsets_s(size_t word_count, double words_per_minute);

/// `synthesis` fitted to the world's schedule: each word's audio moved to start exactly at its
/// onset (relative to the utterance start, at kSampleRateHz), cut with a 5 ms fade where it would
/// run into the next word, so that what is heard and the world's word events agree. The voice
/// spoke at the world's rate, so the moves and cuts are small (docs/audio.md, "Voices").
std::vector<float> fit_to_onsets(const Synthesis& synthesis, const std::vector<double>& onsets_s);

}  // namespace ari_social_sim::audio
