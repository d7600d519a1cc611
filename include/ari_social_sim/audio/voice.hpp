#pragma once

#include <cstdint>
#include <string>

#include "ari_social_sim/model/person_attributes.hpp"

namespace ari_social_sim::audio {

/// How one speaker sounds: an espeak-ng voice variant over its English voice, and the prosody
/// settings espeak-ng takes (docs/audio.md, "Voices").
struct Voice {
  std::string variant;  // espeak-ng variant: m1..m7, f1..f5 or klatt (ARI)
  int pitch{50};        // base pitch, 0..99
  int pitch_range{50};  // intonation range, 0..99
  int rate_wpm{175};    // speaking rate before it is fitted to the world's timing, 80..450

  /// The key of the synthesis cache and of the logs: "f3/62/48/170".
  std::string key() const;
  bool operator==(const Voice& other) const;
};

/// Throws core::RequestError naming the field and its bounds when `voice` is not one espeak-ng
/// can speak with.
void check_voice(const Voice& voice);

/// A person's voice, drawn from the seeded stream of `human_id` (core::rng_streams::kHumanVoice):
/// a variant of their gender (either for non-identified), a pitch that falls with age for men
/// and women as measured speaking fundamentals do, and a rate of 150-190 wpm.
Voice voice_for(uint64_t seed, uint64_t human_id, model::Gender gender, double age_years);

/// ARI's own voice: a fixed, synthetic-sounding one, the same in every run.
Voice ari_voice();

}  // namespace ari_social_sim::audio
