#pragma once

#include <string>

#include "ari_social_sim/TtsGoal.h"

namespace ari_social_sim::nodes {

/// Longest text a request may ask ARI to say: a long paragraph (some 600 words) is under 4 KiB,
/// and each word is played and published on its own.
constexpr size_t kMaxSpokenTextBytes = 4096;
/// Longest wait a /tts goal may ask for before ARI speaks, in seconds: a goal waiting longer holds
/// the floor of the dialogue in the meantime.
constexpr double kMaxWaitBeforeSpeakingS = 60.0;

/// Throws core::RequestError naming `field` unless `text` is at most kMaxSpokenTextBytes of UTF-8
/// without control characters (tab and newline allowed): the words go on to messages, logs and
/// Python clients, which would choke on broken UTF-8 or a NUL.
void check_spoken_text(const std::string& text, const std::string& field);

/// Checks every field of a /tts goal that the simulation reads: rawtext.text (check_spoken_text,
/// and not empty unless text.key asks for a lookup, which is refused as not simulated) and
/// wait_before_speaking (finite, in [0, kMaxWaitBeforeSpeakingS]). Throws core::RequestError naming
/// the field.
void check_tts_goal(const TtsGoal& goal);

}  // namespace ari_social_sim::nodes
