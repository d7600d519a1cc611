#include <gtest/gtest.h>

#include "ari_social_sim/audio/domain_grammar.hpp"
#include "ari_social_sim/audio/speech_recognizer.hpp"
#include "ari_social_sim/audio/speech_synthesizer.hpp"
#include "ari_social_sim/audio/timed_speech.hpp"
#include "ari_social_sim/world/speech_generator.hpp"
#include "audio_scenes.hpp"

namespace ari_social_sim::audio {
namespace {

const std::string kDialogueConfig = std::string(ARI_SOURCE_DIR) + "/config/dialogue/";

std::vector<std::string> shipped_domain_sentences() {
  return read_domain_sentences(kDialogueConfig + "nlg_templates.yaml",
                               kDialogueConfig + "hospital_domain.yaml");
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
  language_model_for(sentences, kPocketsphinxModelDir, &left_out);
  std::printf("%zu domain sentences, %zu with a word outside cmudict left out\n", sentences.size(),
              left_out);
  EXPECT_GT(sentences.size(), 100u);
  EXPECT_LT(left_out, sentences.size() / 10);
  EXPECT_EQ(recognizer_words("Excuse me, where's the Toilet?"), "excuse me where's the toilet");
}

// A live recogniser's first utterance: pocketsphinx's live cepstral mean moves only at the end
// of an utterance, so the first one is decoded with the mean it starts from (the array's, not the
// acoustic model's close-talking prior).
TEST(SpeechRecognizer, TheFirstUtteranceOfAStreamIsRecognised) {
  const std::string question = "hello yes what is the time";
  std::vector<std::string> sentences = shipped_domain_sentences();
  sentences.insert(sentences.end(), 100, question);  // as a scenario's line weighs in the node
  size_t left_out = 0;
  const std::string model = language_model_for(sentences, kPocketsphinxModelDir, &left_out);
  SpeechSynthesizer synthesizer;
  double total_error = 0.0;
  for (const Voice& voice :
       {Voice{"f1", 72, 60, 181}, Voice{"f4", 62, 47, 162}, Voice{"m3", 40, 50, 170}}) {
    RoomSettings room;
    ArrayMixer mixer(room, {}, 5);
    mixer.set_array_pose(test::array_at_origin());
    mixer.set_source_position(1, {1.3, 0.3, 1.55});
    mixer.add({1,
               std::make_shared<const std::vector<float>>(
                   fit_to_onsets(*synthesizer.synthesize(question, voice),
                                 word_onsets_s(world::spoken_words(question).size(), 150.0))),
               kSampleRateHz, false});
    SpeechRecognizer recognizer({kPocketsphinxModelDir, model});
    std::string heard;
    for (int chunk = 0; chunk < 80; ++chunk) {
      for (const Recognition& r : recognizer.process(mixer.render(1024).channels[0].data(), 1024)) {
        heard += r.final ? r.text : "";
      }
    }
    const double error = word_error_rate(question, heard);
    std::printf("%s: \"%s\" (WER %.2f)\n", voice.key().c_str(), heard.c_str(), error);
    total_error += error;
  }
  EXPECT_LE(total_error / 3.0, 0.2);
}

TEST(SpeechRecognizer, AMissingModelIsAClearError) {
  EXPECT_THROW(SpeechRecognizer({"/nonexistent/model", ""}), core::ConfigError);
}

}  // namespace
}  // namespace ari_social_sim::audio
