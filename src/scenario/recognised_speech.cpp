#include "ari_social_sim/scenario/recognised_speech.hpp"

#include <algorithm>

namespace ari_social_sim::scenario {
namespace {

bool names_ari(const std::string& text) {
  const std::vector<std::string> words = dialogue::normalised_words(text);
  return std::find(words.begin(), words.end(), "ari") != words.end();
}

}  // namespace

void RecognisedSpeech::hear(const std::vector<perception::VoiceTranscript>& transcripts,
                            std::vector<dialogue::Perception>& heard) const {
  for (const perception::VoiceTranscript& transcript : transcripts) {
    if (!heard.empty()) {
      dialogue::Perception& previous = heard.back();
      if (previous.speaker != transcript.voice_id && !names_ari(previous.text)) {
        previous.addressees = {transcript.voice_id};  // answered by another person
      }
    }
    dialogue::Perception perception;
    perception.speaker = transcript.voice_id;
    perception.addressees = {dialogue::kRobot};
    perception.text = transcript.text;
    perception.acts = nlu_.understand(transcript.text);
    perception.confidence = transcript.confidence;
    heard.push_back(std::move(perception));
  }
}

}  // namespace ari_social_sim::scenario
