#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "ari_social_sim/dialogue/dialogue_env.hpp"

namespace ari_social_sim::dialogue {

/// Longest text a request may ask ARI to say: a long paragraph (some 600 words) is under 4 KiB,
/// and each word is played and published on its own.
constexpr size_t kMaxSpokenTextBytes = 4096;
/// More acts than any MPGT utterance holds (at most 4) with room to spare; a list beyond it is a
/// client's bug, refused before the NLG realises it.
constexpr size_t kMaxRobotActs = 16;

/// Throws core::RequestError naming `field` unless `text` is at most kMaxSpokenTextBytes of UTF-8
/// without control characters (tab and newline allowed): the words go on to messages, logs and
/// Python clients, which would choke on broken UTF-8 or a NUL.
void check_spoken_text(const std::string& text, const std::string& field);

/// The robot's action of a dialogue step as a client asks for it (dialogue_node's
/// /sim/dialogue/step, the Python DialogueEnv): acts in MPGT notation, addressees among `roles`
/// (each once), ARI's words. Every field is checked before anything is built, so that a refused
/// step leaves the episode as it was. Throws core::RequestError naming the field, e.g.
/// `addressees[1]: expected one of the humans' roles, got 'doctor'`.
RobotAction robot_action_from(const std::vector<std::string>& acts,
                              const std::vector<std::string>& addressees, const std::string& text,
                              const std::vector<std::string>& roles);

}  // namespace ari_social_sim::dialogue
