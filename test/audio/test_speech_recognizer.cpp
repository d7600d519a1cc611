#include <gtest/gtest.h>

#include "ari_social_sim/audio/domain_grammar.hpp"
#include "ari_social_sim/audio/speech_recognizer.hpp"
#include "ari_social_sim/dialogue/nlg.hpp"

namespace ari_social_sim::audio {
namespace {

const std::string kDialogueConfig = std::string(ARI_SOURCE_DIR) + "/config/dialogue/";

std::vector<std::string> shipped_domain_sentences() {
  const dialogue::Nlg nlg(dialogue::NlgTemplates::load(kDialogueConfig + "nlg_templates.yaml"),
                          nullptr, dialogue::NlgMode::kTemplate);
  return domain_sentences(nlg, dialogue::Domain::load(kDialogueConfig + "hospital_domain.yaml"));
}

TEST(WordErrorRate, CountsSubstitutionsInsertionsAndDeletions) {
  EXPECT_DOUBLE_EQ(word_error_rate("where is the toilet", "where is the toilet"), 0.0);
  EXPECT_DOUBLE_EQ(word_error_rate("where is the toilet", "where was the toilet"), 0.25);
  EXPECT_DOUBLE_EQ(word_error_rate("where is the toilet", "where is toilet"), 0.25);
  EXPECT_DOUBLE_EQ(word_error_rate("where is it", "well where is it now"), 2.0 / 3.0);
  EXPECT_DOUBLE_EQ(word_error_rate("hello", ""), 1.0);
}

TEST(DomainLanguageModel, HoldsTheSentencesOfTheDialoguesPeople) {
  const std::vector<std::string> sentences = shipped_domain_sentences();
  size_t left_out = 0;
  arpa_of(sentences, dictionary_words(std::string(kPocketsphinxModelDir) + "/cmudict-en-us.dict"),
          &left_out);
  std::printf("%zu domain sentences, %zu with a word outside cmudict left out\n", sentences.size(),
              left_out);
  EXPECT_GT(sentences.size(), 100u);
  EXPECT_LT(left_out, sentences.size() / 10);
  EXPECT_EQ(recognizer_words("Excuse me, where's the Toilet?"), "excuse me where's the toilet");
}

TEST(SpeechRecognizer, AMissingModelIsAClearError) {
  EXPECT_THROW(SpeechRecognizer({"/nonexistent/model", ""}), core::ConfigError);
}

}  // namespace
}  // namespace ari_social_sim::audio
