// Speech recognition on the array's audio (docs/audio.md, "Speech recognition"): pocketsphinx's
// word error rate on channel 0 for sentences of the dialogue domain, by the speaker's distance,
// the room's noise and a second talker, with the domain's language model and with general
// English. Each condition is one continuous stream (a second of silence between sentences), as a
// live recogniser hears it, decoded by one decoder. Prints a Markdown table.
//
// usage: asr_benchmark [SENTENCES_PER_CONDITION]   (default 8)

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "ari_social_sim/audio/array_mixer.hpp"
#include "ari_social_sim/audio/domain_grammar.hpp"
#include "ari_social_sim/audio/speech_recognizer.hpp"
#include "ari_social_sim/audio/speech_synthesizer.hpp"
#include "ari_social_sim/audio/timed_speech.hpp"
#include "ari_social_sim/audio/world_audio.hpp"
#include "ari_social_sim/world/speech_generator.hpp"

namespace {

using namespace ari_social_sim;

constexpr double kWordsPerMinute = 150.0;
constexpr int64_t kGapSamples = audio::kSampleRateHz;  // a second between sentences

struct Condition {
  double distance_m;
  std::optional<double> snr_db;  // none: no noise to speak of (-120 dBFS)
  bool second_talker;
};

std::shared_ptr<const std::vector<float>> fitted(const std::string& sentence,
                                                 const audio::Voice& voice,
                                                 audio::SpeechSynthesizer& synthesizer) {
  const auto synthesis = synthesizer.synthesize(sentence, voice);
  return std::make_shared<const std::vector<float>>(audio::fit_to_onsets(
      *synthesis, audio::word_onsets_s(world::spoken_words(sentence).size(), kWordsPerMinute)));
}

// Channel 0 of the sentences said one after another by a woman ahead of ARI; with a second
// talker, a man 2 m to the side talks over each sentence.
std::vector<int16_t> stream_of(const std::vector<std::string>& sentences,
                               const Condition& condition, audio::SpeechSynthesizer& synthesizer) {
  audio::RoomSettings room;
  const double speech_at_array = room.speech_level_dbfs - 20.0 * std::log10(condition.distance_m);
  room.noise_level_dbfs = condition.snr_db ? speech_at_array - *condition.snr_db : -120.0;
  const std::vector<audio::Wall> walls{{{-5.0, -4.0}, {5.0, -4.0}},
                                       {{5.0, -4.0}, {5.0, 4.0}},
                                       {{5.0, 4.0}, {-5.0, 4.0}},
                                       {{-5.0, 4.0}, {-5.0, -4.0}}};
  audio::ArrayMixer mixer(room, walls, 7);
  Eigen::Isometry3d array = Eigen::Isometry3d::Identity();
  array.translation() = Eigen::Vector3d(0.0, 0.0, 0.928);
  mixer.set_array_pose(array);
  mixer.set_source_position(1, {condition.distance_m, 0.0, 1.55});
  mixer.set_source_position(2, {0.0, 2.0, 1.55});
  int64_t at = kGapSamples;
  for (size_t i = 0; i < sentences.size(); ++i) {
    const auto speech = fitted(sentences[i], {"f3", 50, 50, 150}, synthesizer);
    mixer.add({1, speech, at, false});
    if (condition.second_talker) {
      const std::string& other = sentences[(i + 1) % sentences.size()];
      mixer.add({2, fitted(other, {"m3", 40, 50, 150}, synthesizer), at + 4000, false});
    }
    at += static_cast<int64_t>(speech->size()) + kGapSamples;
  }
  std::vector<int16_t> channel;
  while (static_cast<int64_t>(channel.size()) < at + kGapSamples) {
    const audio::ArrayChunk chunk = mixer.render(audio::kChunkSamples);
    channel.insert(channel.end(), chunk.channels[0].begin(), chunk.channels[0].end());
  }
  return channel;
}

double stream_wer(const std::vector<std::string>& sentences, const std::vector<int16_t>& stream,
                  const std::string& language_model) {
  audio::SpeechRecognizer recognizer({audio::kPocketsphinxModelDir, language_model});
  std::string heard;
  const auto take = [&heard](const std::vector<audio::Recognition>& out) {
    for (const audio::Recognition& recognition : out) {
      heard += recognition.final ? recognition.text + " " : "";
    }
  };
  for (size_t i = 0; i < stream.size(); i += audio::kChunkSamples) {
    take(recognizer.process(stream.data() + i, std::min(audio::kChunkSamples, stream.size() - i)));
  }
  take(recognizer.flush());
  std::string reference;
  for (const std::string& sentence : sentences) {
    reference += sentence + " ";
  }
  return audio::word_error_rate(reference, heard);
}

}  // namespace

int main(int argc, char** argv) {
  const size_t per_condition = argc > 1 ? std::stoul(argv[1]) : 8;
  const std::string config = std::string(ARI_SOURCE_DIR) + "/config/dialogue/";
  const std::vector<std::string> all =
      audio::read_domain_sentences(config + "nlg_templates.yaml", config + "hospital_domain.yaml");
  size_t left_out = 0;
  const std::set<std::string> known =
      audio::dictionary_words(std::string(audio::kPocketsphinxModelDir) + "/cmudict-en-us.dict");
  const std::string domain_model = audio::arpa_of(all, known, &left_out);
  // Every 997th sentence of three words or more that pocketsphinx can pronounce.
  std::vector<std::string> sentences;
  for (size_t i = 13; sentences.size() < per_condition; i += 997) {
    const std::string& sentence = all[i % all.size()];
    const std::vector<std::string> words = world::spoken_words(sentence);
    const bool pronounceable = std::all_of(
        words.begin(), words.end(), [&known](const auto& word) { return known.count(word) > 0; });
    if (pronounceable && words.size() >= 3) {
      sentences.push_back(sentence);
    }
  }
  audio::SpeechSynthesizer synthesizer;
  std::printf("| distance | noise (SNR) | talkers | WER domain model | WER general English |\n");
  std::printf("|---|---|---|---:|---:|\n");
  for (const double distance : {1.0, 2.0, 4.0}) {
    for (const std::optional<double> snr :
         {std::optional<double>{}, std::optional<double>{20.0}, std::optional<double>{10.0},
          std::optional<double>{0.0}}) {
      for (const bool second : {false, true}) {
        const Condition condition{distance, snr, second};
        const std::vector<int16_t> stream = stream_of(sentences, condition, synthesizer);
        const double domain = stream_wer(sentences, stream, domain_model);
        const double general = stream_wer(sentences, stream, "");
        std::printf("| %.0f m | %s | %d | %.2f | %.2f |\n", distance,
                    snr ? (std::to_string(static_cast<int>(*snr)) + " dB").c_str() : "none",
                    second ? 2 : 1, domain, general);
        std::fflush(stdout);
      }
    }
  }
  return 0;
}
