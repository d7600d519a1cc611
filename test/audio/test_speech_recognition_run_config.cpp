#include <gtest/gtest.h>

#include "ari_social_sim/audio/speech_recognition_run_config.hpp"
#include "expect_config_error.hpp"

namespace ari_social_sim::audio {
namespace {

const std::string kSource = "/speech_recognition parameter";

SpeechRecognitionRunConfig read(const std::string& text) {
  return SpeechRecognitionRunConfig::from_yaml(core::YamlMap::parse(text, kSource));
}

TEST(SpeechRecognitionRunConfig, DefaultsAndOverrides) {
  const SpeechRecognitionRunConfig defaults = read("{}");
  EXPECT_EQ(defaults.language_model, SpeechRecognitionRunConfig::LanguageModel::kDomain);
  EXPECT_EQ(defaults.scenario_line_weight, 100);
  EXPECT_DOUBLE_EQ(defaults.voice_separation_deg, 20.0);
  const SpeechRecognitionRunConfig set =
      read("{language_model: general, scenario_line_weight: 5, voice_range: 2}");
  EXPECT_EQ(set.language_model, SpeechRecognitionRunConfig::LanguageModel::kGeneral);
  EXPECT_EQ(set.scenario_line_weight, 5);
  EXPECT_DOUBLE_EQ(set.voice_range_m, 2.0);
}

TEST(SpeechRecognitionRunConfig, BadValuesAreRefusedNamingTheParameter) {
  world::test::expect_config_error([] { read("{language_model: klingon}"); }, kSource,
                                   {"language_model", "domain or general", "klingon"});
  world::test::expect_config_error([] { read("{scenario_line_weight: 0}"); }, kSource,
                                   {"scenario_line_weight", "[1, 10000]", "0"});
  world::test::expect_config_error([] { read("{voice_separation: 360}"); }, kSource,
                                   {"voice_separation", "[1, 180]", "360"});
  world::test::expect_config_error([] { read("{voice_range: -1}"); }, kSource,
                                   {"voice_range", "[0.1, 10]", "-1"});
  world::test::expect_config_error([] { read("{voices: 3}"); }, kSource, {"voices"});
}

}  // namespace
}  // namespace ari_social_sim::audio
