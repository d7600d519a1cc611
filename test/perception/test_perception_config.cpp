#include <gtest/gtest.h>

#include "../world/expect_config_error.hpp"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/perception/group_perception.hpp"
#include "ari_social_sim/perception/perception_config.hpp"
#include "ari_social_sim/perception/perception_pipeline.hpp"

namespace ari_social_sim::perception {
namespace {

// Expects `body` to throw core::ConfigError naming p.yaml and every fragment.
template <class F>
void expect_config_error(F body, const std::vector<std::string>& fragments,
                         const std::string& source = "p.yaml") {
  world::test::expect_config_error(body, source, fragments);
}

PerceptionConfig parse(const std::string& text) {
  return PerceptionConfig::from_yaml(core::YamlMap::parse(text, "p.yaml"));
}

TEST(PerceptionConfig, DefaultsAreAriAndValidate) {
  const PerceptionConfig config;
  EXPECT_NO_THROW(config.validate());
  EXPECT_DOUBLE_EQ(config.body_camera.field_of_view_deg, 180.0);  // D6.4 §3.5.2
  // The Raspberry Pi camera v2's 62.2 degrees, which D6.4 §3.5.3 rounds to 62 and the rendered
  // head camera uses (model/ari_sensor_geometry.hpp).
  EXPECT_DOUBLE_EQ(config.face_camera.field_of_view_deg, 62.2);
  EXPECT_DOUBLE_EQ(config.persons.location_decay_s, 10.0);  // hri_person_manager
  EXPECT_DOUBLE_EQ(config.persons.forget_after_s, 60.0);
  EXPECT_TRUE(config.errors_enabled);
}

TEST(PerceptionConfig, EmptyFileGivesDefaults) {
  EXPECT_EQ(parse("{}").to_yaml(), PerceptionConfig().to_yaml());
}

TEST(PerceptionConfig, YamlRoundTrips) {
  PerceptionConfig config;
  config.seed = 42;
  config.errors_enabled = false;
  config.body_errors.detection.miss_rate = 0.123456789;
  config.face_errors.emotion_confusion.happy = {0.1, 0.7, 0.1, 0.1};
  config.speech_errors.vocabulary = {"alpha", "beta"};
  config.microphone.language = "fr-FR";
  const PerceptionConfig back = parse(config.to_yaml());
  EXPECT_EQ(back.to_yaml(), config.to_yaml());
  EXPECT_EQ(back.seed, 42u);
  EXPECT_FALSE(back.errors_enabled);
  EXPECT_DOUBLE_EQ(back.body_errors.detection.miss_rate, 0.123456789);
  EXPECT_EQ(back.face_errors.emotion_confusion.happy, (std::vector<double>{0.1, 0.7, 0.1, 0.1}));
  EXPECT_EQ(back.speech_errors.vocabulary, (std::vector<std::string>{"alpha", "beta"}));
  EXPECT_EQ(back.microphone.language, "fr-FR");
}

TEST(PerceptionConfig, TheShippedFileIsTheDefaults) {
  const PerceptionConfig shipped =
      PerceptionConfig::load_file(std::string(ARI_SOURCE_DIR) + "/config/perception.yaml");
  EXPECT_EQ(shipped.to_yaml(), PerceptionConfig().to_yaml());
}

TEST(PerceptionConfig, EachBadFieldIsNamedWithItsBounds) {
  expect_config_error([] { parse("body_errors: {miss_rate: 1.5}"); },
                      {"p.yaml", "body_errors.miss_rate", "[0, 1]", "1.5"});
  expect_config_error([] { parse("face_camera: {range: 0}"); },
                      {"p.yaml", "face_camera.range", "> 0"});
  expect_config_error([] { parse("occlusion: {rays_per_person: 0}"); },
                      {"occlusion.rays_per_person", "[1, 101]"});
  expect_config_error([] { parse("engagement: {field_of_attention_deg: 90}"); },
                      {"engagement.field_of_attention_deg", "(0, 89]"});
  expect_config_error([] { parse("face_errors: {gender_error_rate: -0.1}"); },
                      {"face_errors.gender_error_rate"});
  expect_config_error([] { parse("seed: -3"); }, {"p.yaml: seed", "non-negative integer"});
  expect_config_error([] { parse("errors_enabled: maybe"); }, {"errors_enabled", "true or false"});
}

TEST(PerceptionConfig, UnknownKeysAreErrors) {
  expect_config_error([] { parse("body_camera: {rnage: 3}"); },
                      {"p.yaml", "body_camera", "unknown field(s) rnage"});
  expect_config_error([] { parse("speech: {}"); }, {"top level", "unknown field(s) speech"});
}

TEST(PerceptionConfig, ConfusionRowsNeedFourProbabilitiesSummingToOne) {
  expect_config_error([] { parse("face_errors: {emotion_confusion: {happy: [0.5, 0.5]}}"); },
                      {"p.yaml", "face_errors.emotion_confusion.happy", "4 probabilities"});
  expect_config_error(
      [] { parse("face_errors: {emotion_confusion: {angry: [0.5, 0.5, 0.5, 0]}}"); },
      {"face_errors.emotion_confusion.angry", "summing to 1", "1.5"});
}

TEST(PerceptionConfig, SpeechSharesSumToOneAndVocabularyHasTwoWords) {
  expect_config_error([] { parse("speech_errors: {deletion_share: 0.5}"); },
                      {"p.yaml", "speech_errors.substitution_share", "= 1", "1.25"});
  expect_config_error([] { parse("speech_errors: {vocabulary: [yes, yes]}"); },
                      {"speech_errors.vocabulary", "two different words", "got 1"});
  expect_config_error([] { parse("speech_errors: {vocabulary: [good morning, yes]}"); },
                      {"speech_errors.vocabulary", "single words", "'good morning'"});
  // Without word errors no vocabulary is needed.
  EXPECT_NO_THROW(parse("speech_errors: {word_error_rate: 0, vocabulary: []}"));
}

TEST(PerceptionConfig, PersonIdStyleIsHumanOrRandom) {
  EXPECT_EQ(parse("persons: {id_style: random}").persons.id_style, "random");
  expect_config_error([] { parse("persons: {id_style: anonymous}"); },
                      {"p.yaml: persons.id_style", "expected human or random", "anonymous"});
  PerceptionConfig built;
  built.persons.id_style = "";
  EXPECT_THROW(built.validate(), core::ConfigError);
}

TEST(PerceptionConfig, PersonsForgottenNoSoonerThanTheirConfidenceFades) {
  EXPECT_DOUBLE_EQ(parse("persons: {forget_after: 10}").persons.forget_after_s, 10.0);
  expect_config_error([] { parse("persons: {location_decay: 10, forget_after: 9.5}"); },
                      {"persons.forget_after", "at least location_decay (10)", "got 9.5"});
  expect_config_error([] { parse("persons: {forget_after: 0}"); },
                      {"p.yaml: persons.forget_after", "> 0", "0"});
}

TEST(PerceptionConfig, ValidateRefusesABadValueBuiltInCode) {
  PerceptionConfig config;
  config.body_errors.detection.miss_rate = 1.5;
  expect_config_error([&] { config.validate(); }, {"body_errors.miss_rate", "[0, 1]", "got 1.5"},
                      "PerceptionConfig");
  // The pipeline checks the config it is given.
  expect_config_error([&] { PerceptionPipeline{config}; }, {"body_errors.miss_rate"},
                      "PerceptionConfig");
  config = PerceptionConfig{};
  config.face_errors.emotion_confusion.happy = {0.5, 0.5, 0.5, 0.0};
  expect_config_error([&] { config.validate(); },
                      {"face_errors.emotion_confusion.happy", "summing to 1", "a sum of 1.5"},
                      "PerceptionConfig");
}

TEST(GroupConfig, ValidateRefusesABadValueBuiltInCode) {
  GroupConfig config;
  EXPECT_NO_THROW(config.validate());
  config.membership_window_frames = 0;
  expect_config_error([&] { GroupPerception{config}; },
                      {"GroupConfig: membership_window_frames", "[1, 10000]", "got 0"},
                      "GroupConfig");
  config = GroupConfig{};
  config.gcff.mdl = -1.0;
  expect_config_error([&] { config.validate(); }, {"mdl", "> 0", "got -1"}, "GroupConfig");
}

TEST(PerceptionConfig, EyesAboveHips) {
  expect_config_error([] { parse("human_model: {hip_height: 1.0, eye_height: 0.9}"); },
                      {"human_model.eye_height", "more than hip_height"});
  expect_config_error(
      [] { parse("human_model: {seated_hip_height: 0.6, seated_eye_height: 0.5}"); },
      {"human_model.seated_eye_height", "more than seated_hip_height (0.6)", "0.5"});
  expect_config_error([] { parse("human_model: {seated_hip_height: -0.2}"); },
                      {"human_model.seated_hip_height"});
}

TEST(PerceptionConfig, WithoutErrorsZeroesEveryErrorModelOnly) {
  const PerceptionConfig off = PerceptionConfig().without_errors();
  EXPECT_FALSE(off.errors_enabled);
  EXPECT_NO_THROW(off.validate());
  for (const DetectionErrors* d : {&off.body_errors.detection, &off.face_errors.detection}) {
    EXPECT_EQ(d->miss_rate + d->miss_rate_at_max_range + d->miss_rate_at_fov_border +
                  d->miss_rate_occluded + d->reid_after_occlusion + d->reid_after_leaving_fov +
                  d->reid_rate_per_min,
              0.0);
  }
  EXPECT_EQ(off.body_errors.pose.position_stddev_m(5.0), 0.0);
  EXPECT_EQ(off.face_errors.pose.orientation_stddev_deg(5.0), 0.0);
  EXPECT_EQ(off.face_errors.age_noise_years + off.face_errors.gender_error_rate +
                off.face_errors.mask_error_rate,
            0.0);
  const EmotionConfusion identity = EmotionConfusion::identity();
  EXPECT_EQ(off.face_errors.emotion_confusion.neutral, identity.neutral);
  EXPECT_EQ(off.face_errors.emotion_confusion.disturbed, identity.disturbed);
  EXPECT_EQ(off.speech_errors.word_error_rate + off.speech_errors.misattribution_rate, 0.0);
  EXPECT_EQ(off.matchers.recognition_rate, 1.0);
  EXPECT_EQ(off.matchers.confidence_noise, 0.0);
  // Sensors stay.
  EXPECT_DOUBLE_EQ(off.face_camera.range_m, PerceptionConfig().face_camera.range_m);
  EXPECT_EQ(PerceptionConfig().effective().to_yaml(), PerceptionConfig().to_yaml());
  PerceptionConfig disabled;
  disabled.errors_enabled = false;
  EXPECT_EQ(disabled.effective().to_yaml(), off.to_yaml());
}

TEST(PerceptionConfig, MissingFileIsNamed) {
  expect_config_error([] { PerceptionConfig::load_file("/nonexistent/perception.yaml"); },
                      {"cannot open"}, "/nonexistent/perception.yaml");
}

}  // namespace
}  // namespace ari_social_sim::perception
