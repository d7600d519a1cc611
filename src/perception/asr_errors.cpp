#include "ari_social_sim/perception/asr_errors.hpp"

#include <sstream>

namespace ari_social_sim::perception {

AsrErrors::AsrErrors(const SpeechErrors& errors, core::Rng rng) : errors_(errors), rng_(rng) {}

const std::string& AsrErrors::vocabulary_word_other_than(const std::string& word) {
  // The vocabulary has at least two distinct words when substitutions can happen (validated),
  // so this ends.
  while (true) {
    const std::string& candidate =
        errors_.vocabulary[rng_.uniform_index(errors_.vocabulary.size())];
    if (candidate != word) {
      return candidate;
    }
  }
}

void AsrErrors::hear(const std::string& word, std::vector<std::string>& transcript) {
  const double wer = errors_.word_error_rate;
  if (wer <= 0.0) {
    transcript.push_back(word);
    return;
  }
  const double draw = rng_.uniform();
  const double substitution = wer * errors_.substitution_share;
  const double deletion = wer * errors_.deletion_share;
  if (draw < substitution) {
    transcript.push_back(vocabulary_word_other_than(word));
  } else if (draw >= substitution + deletion) {
    transcript.push_back(word);
  }
  if (rng_.bernoulli(wer * errors_.insertion_share)) {
    transcript.push_back(vocabulary_word_other_than(""));
  }
}

std::vector<std::string> split_words(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> words;
  for (std::string word; in >> word;) {
    words.push_back(word);
  }
  return words;
}

std::string join_words(const std::vector<std::string>& words) {
  std::string text;
  for (const std::string& word : words) {
    text += (text.empty() ? "" : " ") + word;
  }
  return text;
}

}  // namespace ari_social_sim::perception
