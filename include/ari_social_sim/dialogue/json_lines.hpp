#pragma once

#include <string>

#include "ari_social_sim/dialogue/utterance.hpp"

namespace ari_social_sim::dialogue {

/// One utterance as one line of JSON (no newline): the keys dialogue, turn, speaker, addressee
/// (a string, or a list for several addressees), text, acts and goals (MPGT notation strings),
/// start_s and end_s, and for human utterances `heard`, what ARI perceived (dropped, speaker,
/// addressee, text, acts, confidence). Numbers have fixed decimals, so equal input gives equal
/// bytes.
std::string utterance_json(int dialogue, const Utterance& utterance);

}  // namespace ari_social_sim::dialogue
