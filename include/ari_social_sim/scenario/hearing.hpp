#pragma once

#include "ari_social_sim/core/config_fields.hpp"

namespace ari_social_sim::scenario {

/// Where ARI's side of a `converse` takes what the people said from: the dialogue's simulated
/// perceptions (acts through its error layer), or speech recognition's final transcripts, which
/// ARI understands itself (RecognisedSpeech; speech:=audio, where pocketsphinx listens to the
/// microphone array).
enum class Hearing { kSimulated, kRecognised };
inline constexpr core::Choice<Hearing> kHearings[] = {{Hearing::kSimulated, "simulated"},
                                                      {Hearing::kRecognised, "recognised"}};

}  // namespace ari_social_sim::scenario
