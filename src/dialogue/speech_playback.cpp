#include "ari_social_sim/dialogue/speech_playback.hpp"

#include "ari_social_sim/dialogue/text.hpp"

namespace ari_social_sim::dialogue {

void SpeechPlayback::begin(uint32_t speaker_id, const std::string& content, double called_s) {
  *this = SpeechPlayback{};
  speaker_id_ = speaker_id;
  content_ = content;
  called_s_ = called_s;
  done_ = false;
}

void SpeechPlayback::follow(const SpeakerState* speaker) {
  if (done_) {
    return;
  }
  if (speaker == nullptr) {
    done_ = true;  // a speaker removed from the world mid-utterance has stopped speaking
    return;
  }
  const bool saying_it =
      speaker->is_speaking && speaker->content == content_ && speaker->start_s >= called_s_ - 1e-9;
  if (!started_) {
    if (saying_it) {
      started_ = true;
      start_s_ = speaker->start_s;
      words_started_ = speaker->word_index + 1;
    }
    return;
  }
  if (saying_it && speaker->start_s == start_s_) {
    words_started_ = speaker->word_index + 1;
  } else {
    // Played to its end: every word was started, including any whose states were missed.
    words_started_ = split_words(content_).size();
    done_ = true;
  }
}

}  // namespace ari_social_sim::dialogue
