#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace ari_social_sim::audio {

/// Where Debian's pocketsphinx-en-us puts the US English model.
inline constexpr const char* kPocketsphinxModelDir = "/usr/share/pocketsphinx/model/en-us";

/// What the recogniser listens for: a language model of the sentences the dialogue domain's
/// people say (ARPA text, domain_grammar.hpp), or pocketsphinx's general English model.
struct RecognizerSettings {
  std::string model_dir{kPocketsphinxModelDir};
  std::string language_model_arpa;  // empty: the general English model (en-us.lm.bin)
};

/// A hypothesis about what was said: while an utterance goes on (incremental) and at its end
/// (final), as ROS4HRI's LiveSpeech carries them.
struct Recognition {
  std::string text;
  double confidence{0.0};  // the decoder's posterior of the hypothesis, 0..1
  bool final{false};
};

/// Speech recognition with Debian's pocketsphinx on 16 kHz 16-bit audio, its own voice activity
/// detection splitting the stream into utterances.
class SpeechRecognizer {
 public:
  /// Throws core::ConfigError naming the model folder when pocketsphinx cannot load it or the
  /// grammar.
  explicit SpeechRecognizer(const RecognizerSettings& settings);
  ~SpeechRecognizer();
  SpeechRecognizer(const SpeechRecognizer&) = delete;
  SpeechRecognizer& operator=(const SpeechRecognizer&) = delete;

  /// Feeds `count` samples; returns the hypotheses they produced: an incremental one when the
  /// current utterance's best text changed, a final one when its speech ended.
  std::vector<Recognition> process(const int16_t* samples, size_t count);
  /// Ends the current utterance, if any, and returns its final hypothesis.
  std::vector<Recognition> flush();

 private:
  struct Decoder;
  void use_language_model(const std::string& arpa);
  Recognition final_recognition();
  std::unique_ptr<Decoder> decoder_;
  bool in_utterance_{false};
  std::string last_partial_;
};

/// Word error rate of `hypothesis` against `reference` (words split at spaces): the Levenshtein
/// distance between the word sequences over the reference's length.
double word_error_rate(const std::string& reference, const std::string& hypothesis);

}  // namespace ari_social_sim::audio
