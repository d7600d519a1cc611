#include "ari_social_sim/audio/speech_recognizer.hpp"

#include <pocketsphinx.h>
#include <sphinxbase/cmn.h>
#include <sphinxbase/feat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <string>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/dialogue/text.hpp"

namespace ari_social_sim::audio {
namespace {

constexpr const char* kDomainSearch = "domain";

// The cepstral mean pocketsphinx's live CMN settles on for speech on the array's processed
// channel (read from its log over minutes of the simulated voices 1-4 m away): where a
// recogniser that has been listening in the room starts.
constexpr std::array<mfcc_t, 13> kArrayCepstralMean = {
    41.5f, 2.8f, -4.5f, 6.4f, -12.0f, 3.4f, -8.5f, -1.9f, 1.0f, 5.7f, -4.6f, 3.8f, 6.1f};

// The mean of the hypothesis' words' posteriors (silences and fillers left out): the whole
// utterance's posterior, their product, falls towards 0 with its length alone.
double mean_word_posterior(ps_decoder_t* ps) {
  logmath_t* logmath = ps_get_logmath(ps);
  double sum = 0.0;
  size_t words = 0;
  for (ps_seg_t* seg = ps_seg_iter(ps); seg != nullptr; seg = ps_seg_next(seg)) {
    const std::string word = ps_seg_word(seg);
    if (word.empty() || word.front() == '<' || word.front() == '[') {
      continue;
    }
    int32 acoustic = 0, language = 0, backoff = 0;
    sum += logmath_exp(logmath, ps_seg_prob(seg, &acoustic, &language, &backoff));
    ++words;
  }
  return words == 0 ? 0.0 : sum / words;
}

}  // namespace

struct SpeechRecognizer::Decoder {
  ps_decoder_t* ps{nullptr};
  ~Decoder() {
    if (ps != nullptr) {
      ps_free(ps);
    }
  }
};

SpeechRecognizer::SpeechRecognizer(const RecognizerSettings& settings)
    : decoder_(std::make_unique<Decoder>()) {
  const std::string hmm = settings.model_dir + "/en-us";
  const std::string dict = settings.model_dir + "/cmudict-en-us.dict";
  const std::string lm = settings.model_dir + "/en-us.lm.bin";
  cmd_ln_t* config =
      cmd_ln_init(nullptr, ps_args(), TRUE, "-hmm", hmm.c_str(), "-dict", dict.c_str(), "-lm",
                  lm.c_str(), "-samprate", "16000", "-logfn", "/dev/null", nullptr);
  decoder_->ps = config != nullptr ? ps_init(config) : nullptr;
  if (config != nullptr) {
    cmd_ln_free_r(config);
  }
  if (decoder_->ps == nullptr) {
    throw core::ConfigError("speech recognition: pocketsphinx could not load its model from " +
                            settings.model_dir +
                            " (expected en-us/, cmudict-en-us.dict and en-us.lm.bin: Debian's "
                            "pocketsphinx-en-us, scripts/install_deps.sh)");
  }
  // The acoustic model's prior cepstral mean is a close-talking microphone's; live CMN only moves
  // from it at the end of an utterance, so the first one heard would be decoded with it.
  cmn_live_set(ps_get_feat(decoder_->ps)->cmn_struct, kArrayCepstralMean.data());
  if (!settings.language_model_arpa.empty()) {
    use_language_model(settings.language_model_arpa);
  }
  ps_start_utt(decoder_->ps);
}

SpeechRecognizer::~SpeechRecognizer() = default;

void SpeechRecognizer::use_language_model(const std::string& arpa) {
  // pocketsphinx reads language models from files only.
  char path[] = "/tmp/ari_domain_lm_XXXXXX";
  const int fd = mkstemp(path);
  const bool written =
      fd >= 0 && write(fd, arpa.data(), arpa.size()) == static_cast<ssize_t>(arpa.size());
  if (fd >= 0) {
    close(fd);
  }
  const bool loaded = written && ps_set_lm_file(decoder_->ps, kDomainSearch, path) == 0 &&
                      ps_set_search(decoder_->ps, kDomainSearch) == 0;
  unlink(path);
  if (!loaded) {
    throw core::ConfigError(
        "speech recognition: pocketsphinx refused the domain language model (a word outside "
        "cmudict-en-us.dict, or no space in /tmp)");
  }
}

Recognition SpeechRecognizer::final_recognition() {
  ps_end_utt(decoder_->ps);
  int32 score = 0;
  const char* hypothesis = ps_get_hyp(decoder_->ps, &score);
  Recognition recognition;
  recognition.text = hypothesis != nullptr ? hypothesis : "";
  recognition.confidence = mean_word_posterior(decoder_->ps);
  recognition.final = true;
  ps_start_utt(decoder_->ps);
  in_utterance_ = false;
  last_partial_.clear();
  return recognition;
}

std::vector<Recognition> SpeechRecognizer::process(const int16_t* samples, size_t count) {
  std::vector<Recognition> out;
  ps_process_raw(decoder_->ps, samples, count, FALSE, FALSE);
  const bool in_speech = ps_get_in_speech(decoder_->ps) != 0;
  if (in_speech) {
    in_utterance_ = true;
    int32 score = 0;
    const char* partial = ps_get_hyp(decoder_->ps, &score);
    if (partial != nullptr && *partial != '\0' && last_partial_ != partial) {
      last_partial_ = partial;
      out.push_back({last_partial_, 0.0, false});
    }
  } else if (in_utterance_) {
    Recognition recognition = final_recognition();
    if (!recognition.text.empty()) {
      out.push_back(std::move(recognition));
    }
  }
  return out;
}

std::vector<Recognition> SpeechRecognizer::flush() {
  std::vector<Recognition> out;
  if (in_utterance_) {
    Recognition recognition = final_recognition();
    if (!recognition.text.empty()) {
      out.push_back(std::move(recognition));
    }
  }
  return out;
}

double word_error_rate(const std::string& reference, const std::string& hypothesis) {
  const std::vector<std::string> ref = dialogue::split_words(reference);
  const std::vector<std::string> hyp = dialogue::split_words(hypothesis);
  if (ref.empty()) {
    return hyp.empty() ? 0.0 : 1.0;
  }
  std::vector<size_t> previous(hyp.size() + 1), current(hyp.size() + 1);
  for (size_t j = 0; j <= hyp.size(); ++j) {
    previous[j] = j;
  }
  for (size_t i = 1; i <= ref.size(); ++i) {
    current[0] = i;
    for (size_t j = 1; j <= hyp.size(); ++j) {
      const size_t substitute = previous[j - 1] + (ref[i - 1] == hyp[j - 1] ? 0 : 1);
      current[j] = std::min({substitute, previous[j] + 1, current[j - 1] + 1});
    }
    std::swap(previous, current);
  }
  return static_cast<double>(previous[hyp.size()]) / ref.size();
}

}  // namespace ari_social_sim::audio
