#include <gtest/gtest.h>

#include <cstdio>

#include "ari_social_sim/dialogue/dialogue_config.hpp"
#include "ari_social_sim/dialogue/human_nlu.hpp"
#include "test_helpers.hpp"

namespace ari_social_sim::dialogue {
namespace {

class HumanNluTest : public ::testing::Test {
 protected:
  HumanNluTest()
      : setup_(DialogueSetup::create(DialogueConfig::defaults(ARI_DIALOGUE_CONFIG_DIR))),
        nlu_(*setup_->nlg, setup_->domain, setup_->corpus_or_null()) {}

  std::string understood(const std::string& text) const {
    return acts_to_string(nlu_.understand(text));
  }

  std::unique_ptr<DialogueSetup> setup_;
  HumanNlu nlu_;
};

// What a recogniser writes: lower case, no punctuation, so no sentence boundaries either.
std::string as_recognised(const std::string& text) {
  std::string words;
  for (const std::string& word : normalised_words(text)) {
    words += (words.empty() ? "" : " ") + word;
  }
  return words;
}

TEST_F(HumanNluTest, EveryRequestOfTheDomainIsUnderstoodFromRecognisedText) {
  // Each goal's requests in every tenth form of every human template (all 11,301 take 12 s),
  // written as a recogniser does, come back as a request for that goal.
  constexpr size_t kStride = 10;
  size_t listed = 0;
  int forms = 0;
  int right = 0;
  for (const PredicateSpec& predicate : setup_->domain.predicates()) {
    for (const DomainObject& object : predicate.objects) {
      const Goal goal{{}, predicate.name, object.path};
      for (const DialogueAct& ask : setup_->domain.ask_acts(goal)) {
        for (const std::string& text : setup_->nlg->template_texts(false, ask)) {
          if (listed++ % kStride != 0) {
            continue;
          }
          ++forms;
          for (const DialogueAct& act : nlu_.understand(as_recognised(text))) {
            const auto stated = setup_->domain.goal_of_request(act);
            if (stated && stated->predicate == goal.predicate && stated->object == goal.object) {
              ++right;
              break;
            }
          }
        }
      }
    }
  }
  const double share = static_cast<double>(right) / forms;
  std::printf("[ measured ] %d of %d request forms understood as their goal (%.3f)\n", right, forms,
              share);
  EXPECT_GT(forms, 1000);  // 1,131 of 11,301
  EXPECT_GE(share, 0.95);
}

TEST_F(HumanNluTest, WhatPeopleSayBesidesRequests) {
  // Recogniser-style text: lower case, no punctuation, a form of the templates.
  EXPECT_EQ(understood("oh hello there how are you"), "greet()");
  EXPECT_EQ(understood("thank you so much that's very helpful"), "thank()");
  EXPECT_EQ(understood("right goodbye see you"), "bye()");
  EXPECT_EQ(understood("sorry would you mind repeating that"), "r-repet()");
  EXPECT_EQ(understood("excuse me where is the toilets"), "request(location(toilet))");
  EXPECT_EQ(understood("i can't hear you with all this noise"), "cant-hear()");
}

TEST_F(HumanNluTest, TextWithNothingOfTheDomainIsNotUnderstood) {
  EXPECT_EQ(understood(""), "");
  EXPECT_EQ(understood("xylophone zebra quantum"), "");
}

}  // namespace
}  // namespace ari_social_sim::dialogue
