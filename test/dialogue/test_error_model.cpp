#include <gtest/gtest.h>

#include "ari_social_sim/core/config_reader.hpp"
#include "ari_social_sim/dialogue/error_model.hpp"
#include "test_helpers.hpp"

namespace ari_social_sim::dialogue {
namespace {

using testing::config_path;
using testing::expect_config_error;

Utterance request_utterance() {
  Utterance u;
  u.speaker = "patient";
  u.addressees = {kRobot};
  u.text = "could you tell me where the toilets are please";  // 9 words
  u.acts = {parse_act("request(location(toilet))", "t")};
  return u;
}

TEST(ErrorModel, WordErrorRateMeetsTarget) {
  const Domain domain = Domain::load(config_path("hospital_domain.yaml"));
  ErrorModelConfig config;
  config.word_error_rate = 0.15;
  const ErrorModel model(config, domain, {"um", "the", "cafe"});
  core::Rng rng(5);
  int errors = 0;
  const int utterances = 2000;
  for (int i = 0; i < utterances; ++i) {
    std::string text = request_utterance().text;
    errors += model.corrupt_words(text, rng);
  }
  // 2000 x 9 = 18 000 words at 0.15: sd of the rate 0.0027.
  EXPECT_NEAR(errors / (utterances * 9.0), 0.15, 0.01);
}

TEST(ErrorModel, RatesOfDropMisattributionAddresseeAndConfusion) {
  const Domain domain = Domain::load(config_path("hospital_domain.yaml"));
  ErrorModelConfig config;
  config.drop_rate = 0.1;
  config.misattribution_rate = 0.2;
  config.wrong_addressee_rate = 0.3;
  config.semantic_error_rate = 0.4;
  config.word_error_rate = 0.0;
  const ErrorModel model(config, domain, {});
  const std::vector<std::string> humans{"patient", "companion"};
  core::Rng rng(11);
  int dropped = 0, misattributed = 0, readdressed = 0, confused = 0;
  const int n = 20000;
  const Utterance u = request_utterance();
  for (int i = 0; i < n; ++i) {
    const Perception p = model.apply(u, humans, rng);
    if (p.dropped) {
      ++dropped;
      continue;
    }
    misattributed += p.speaker != "patient" ? 1 : 0;
    readdressed += p.addressees != u.addressees ? 1 : 0;
    confused += p.acts != u.acts ? 1 : 0;
    EXPECT_NEAR(p.confidence, 1.0, 0.3);  // no word errors: 1 + N(0, 0.05), clamped
  }
  const double heard = n - dropped;
  EXPECT_NEAR(dropped / double(n), 0.1, 0.01);
  EXPECT_NEAR(misattributed / heard, 0.2, 0.015);
  EXPECT_NEAR(readdressed / heard, 0.3, 0.015);
  // A confusion may redraw the same name (1 of ~24 intents, 1 of the slots or objects): a little
  // under 0.4.
  EXPECT_NEAR(confused / heard, 0.38, 0.03);
}

TEST(ErrorModel, ConfigValidation) {
  EXPECT_NO_THROW(ErrorModelConfig{}.validate());
  ErrorModelConfig bad;
  bad.drop_rate = 1.5;
  expect_config_error([&] { bad.validate(); }, {"ErrorModelConfig: drop_rate", "[0, 1]"});
  bad = ErrorModelConfig{};
  bad.intent_share = 0.8;
  expect_config_error([&] { bad.validate(); },
                      {"ErrorModelConfig: slot_share", "intent_share + slot_share <= 1", "1.1"});
  expect_config_error(
      [] {
        core::read_fields<ErrorModelConfig>(core::YamlMap::parse("word_eror_rate: 0.1", "e.yaml"));
      },
      {"e.yaml", "word_eror_rate"});
  const auto read =
      core::read_fields<ErrorModelConfig>(core::YamlMap::parse("word_error_rate: 0.25", "e.yaml"));
  EXPECT_DOUBLE_EQ(read.word_error_rate, 0.25);
}

}  // namespace
}  // namespace ari_social_sim::dialogue
