#include <gtest/gtest.h>

#include "ari_social_sim/dialogue/dialogue_act.hpp"
#include "ari_social_sim/scenario/recognised_speech.hpp"

namespace ari_social_sim::scenario {
namespace {

class RecognisedSpeechTest : public ::testing::Test {
 protected:
  RecognisedSpeechTest()
      : setup_(dialogue::DialogueSetup::create(
            dialogue::DialogueConfig::defaults(dialogue::default_dialogue_config_dir()))),
        speech_(*setup_) {}

  std::unique_ptr<dialogue::DialogueSetup> setup_;
  RecognisedSpeech speech_;
  std::vector<dialogue::Perception> heard_;
};

TEST_F(RecognisedSpeechTest, ATranscriptBecomesAnUtteranceToAriWithItsActs) {
  speech_.hear({{"voice1", "hello where is the cafeteria", 0.7}}, heard_);
  ASSERT_EQ(heard_.size(), 1u);
  EXPECT_EQ(heard_[0].speaker, "voice1");
  EXPECT_EQ(heard_[0].addressees, std::vector<std::string>{"ARI"});
  EXPECT_EQ(dialogue::acts_to_string(heard_[0].acts), "request(location(cafe))");
  EXPECT_DOUBLE_EQ(heard_[0].confidence, 0.7);
}

TEST_F(RecognisedSpeechTest, AnUtteranceAnotherVoiceAnswersWasForThatPerson) {
  // The patient asks, the companion answers before ARI speaks: the question was the companion's.
  speech_.hear({{"voice1", "where would i find the toilets", 0.7}}, heard_);
  speech_.hear({{"voice2", "i think it's over there", 0.6}}, heard_);
  ASSERT_EQ(heard_.size(), 2u);
  EXPECT_EQ(heard_[0].addressees, std::vector<std::string>{"voice2"});
  EXPECT_EQ(heard_[1].addressees, std::vector<std::string>{"ARI"});
}

TEST_F(RecognisedSpeechTest, NamingAriOrGoingOnKeepsItAddressedToAri) {
  speech_.hear({{"voice1", "ari where is the cafeteria", 0.7},
                {"voice2", "yes please", 0.6},
                {"voice2", "and the toilets", 0.5}},
               heard_);
  ASSERT_EQ(heard_.size(), 3u);
  EXPECT_EQ(heard_[0].addressees, std::vector<std::string>{"ARI"});  // names ARI
  EXPECT_EQ(heard_[1].addressees, std::vector<std::string>{"ARI"});  // same voice goes on
  EXPECT_EQ(heard_[2].addressees, std::vector<std::string>{"ARI"});
}

}  // namespace
}  // namespace ari_social_sim::scenario
