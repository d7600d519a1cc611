#pragma once

#include <string>
#include <vector>

#include "ari_social_sim/core/rng.hpp"
#include "ari_social_sim/perception/perception_config.hpp"

namespace ari_social_sim::perception {

/// Word errors of automatic speech recognition. Each spoken word is, independently, substituted
/// by a different vocabulary word (probability WER x substitution_share), deleted (WER x
/// deletion_share) or kept, and then followed by an inserted vocabulary word (WER x
/// insertion_share); the expected (S + D + I) / N is the configured word error rate.
class AsrErrors {
 public:
  AsrErrors(const SpeechErrors& errors, core::Rng rng);

  /// Appends what the recogniser makes of one spoken word to `transcript`.
  void hear(const std::string& word, std::vector<std::string>& transcript);

 private:
  const std::string& vocabulary_word_other_than(const std::string& word);

  SpeechErrors errors_;
  core::Rng rng_;
};

/// Splits an utterance into its words (separated by whitespace).
std::vector<std::string> split_words(const std::string& text);
/// Joins words with single spaces.
std::string join_words(const std::vector<std::string>& words);

}  // namespace ari_social_sim::perception
