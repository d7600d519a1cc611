#pragma once

#include <string>

#include "ari_social_sim/TtsGoal.h"

namespace ari_social_sim::nodes {

/// Longest wait a /tts goal may ask for before ARI speaks, in seconds: a goal waiting longer holds
/// the floor of the dialogue in the meantime.
constexpr double kMaxWaitBeforeSpeakingS = 60.0;

/// Checks every field of a /tts goal that the simulation reads: rawtext.text
/// (dialogue::check_spoken_text, and not empty unless text.key asks for a lookup, which is refused
/// as not simulated) and wait_before_speaking (finite, in [0, kMaxWaitBeforeSpeakingS]). Throws
/// core::RequestError naming the field.
void check_tts_goal(const TtsGoal& goal);

}  // namespace ari_social_sim::nodes
