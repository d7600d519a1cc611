#pragma once

#include <vector>

#include "ari_social_sim/dialogue/dialogue_config.hpp"
#include "ari_social_sim/dialogue/human_nlu.hpp"
#include "ari_social_sim/dialogue/utterance.hpp"
#include "ari_social_sim/perception/voice_transcript.hpp"

namespace ari_social_sim::scenario {

/// The people's utterances as ARI hears them through speech recognition, as the dialogue's
/// perceptions: each final transcript understood by HumanNlu, said by its voice. Recognition tells
/// no addressee, so an utterance counts as addressed to ARI unless another voice speaks next
/// before ARI does and it does not name ARI: the heuristic the dialogue statistics apply to MPGT
/// (dialogue::is_human_to_human), applied as the talk goes on.
class RecognisedSpeech {
 public:
  /// The NLU from the setup's templates, domain and corpus (a tenth of a second).
  explicit RecognisedSpeech(const dialogue::DialogueSetup& setup)
      : nlu_(*setup.nlg, setup.domain, setup.corpus_or_null()) {}

  /// Appends what `transcripts` say to `heard`, the utterances heard since ARI's last turn, and
  /// re-addresses the last of them to the first new voice that answers it.
  void hear(const std::vector<perception::VoiceTranscript>& transcripts,
            std::vector<dialogue::Perception>& heard) const;

 private:
  dialogue::HumanNlu nlu_;
};

}  // namespace ari_social_sim::scenario
