#include <gtest/gtest.h>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/world/simulation.hpp"
#include "ari_social_sim/world/speech_generator.hpp"
#include "scene_builders.hpp"

namespace ari_social_sim::world {
namespace {

// D6.4 §3.3.3: a 10-word utterance at 120 wpm lasts 10 x 0.5 s = 5.0 s, played word by word.
TEST(SpeechGenerator, TenWordsAt120WpmLastFiveSecondsWordByWord) {
  Simulation simulation(test::square_room(6.0), SimulationConfig{0.05, 1, 0.05});
  HumanSpec spec;
  spec.id = 10;
  spec.pose.position = {3.0, 3.0};
  spec.words_per_minute = 120.0;
  const Human& human = simulation.add_human(spec);
  simulation.step();  // start at t = 0.05 s, off the origin on purpose
  const double start = simulation.time_s();
  EXPECT_DOUBLE_EQ(
      simulation.say(10, "INFORM:TEST", "one two three four five six seven eight nine ten"), 5.0);

  std::vector<std::string> heard;
  while (human.speech().is_speaking()) {
    simulation.step();
    const std::string& word = human.speech().current_word();
    if (!word.empty() && (heard.empty() || heard.back() != word)) {
      heard.push_back(word);
    }
    ASSERT_LT(simulation.time_s(), start + 10.0);
  }
  const std::vector<std::string> expected{"one", "two",   "three", "four", "five",
                                          "six", "seven", "eight", "nine", "ten"};
  EXPECT_EQ(heard, expected);
  const SpeechRecord& record = human.speech().history().at(0);
  EXPECT_EQ(record.act, "INFORM:TEST");
  EXPECT_DOUBLE_EQ(record.start_s, start);
  EXPECT_GE(record.end_s - record.start_s, 5.0 - 1e-9);
  EXPECT_LE(record.end_s - record.start_s, 5.0 + 0.05 + 1e-9);
  EXPECT_FALSE(record.interrupted);
  EXPECT_EQ(human.speech().previous()->act, "INFORM:TEST");
}

TEST(SpeechGenerator, SayingAgainInterruptsAndRecordsTheCutOffAct) {
  SpeechGenerator speech(150.0);
  speech.say("A", "first utterance here", 1.0);
  speech.say("B", "second", 1.2);
  ASSERT_EQ(speech.history().size(), 1u);
  EXPECT_TRUE(speech.history()[0].interrupted);
  EXPECT_DOUBLE_EQ(speech.history()[0].end_s, 1.2);
  EXPECT_EQ(speech.act(), "B");
}

TEST(SpeechGenerator, EmptyContentOrActIsRejected) {
  SpeechGenerator speech(150.0);
  EXPECT_THROW(speech.say("A", "   ", 0.0), core::RequestError);
  EXPECT_THROW(speech.say("", "hello", 0.0), core::RequestError);
  EXPECT_FALSE(speech.is_speaking());
}

TEST(SpeechGenerator, ContentAndActAreBounded) {
  // So that a client cannot make the world hold, and publish with every state, megabytes of speech.
  SpeechGenerator speech(150.0);
  std::string words;
  while (words.size() + 5 <= SpeechGenerator::kMaxContentBytes) {
    words += "word ";
  }
  speech.say("INFORM", words, 0.0);  // 4095 bytes
  try {
    speech.say("INFORM", words + "words", 0.0);
    FAIL() << "accepted 4100 bytes";
  } catch (const core::RequestError& e) {
    EXPECT_STREQ(e.what(), "say: content: expected at most 4096 bytes, got 4100");
  }
  EXPECT_THROW(speech.say(std::string(257, 'A'), "hello", 0.0), core::RequestError);
  EXPECT_EQ(speech.content(), words);  // the refused acts left the one in progress alone
}

// An act is what consumers match patterns against and split at `;`: one notation, checked.
TEST(SpeechGenerator, ActsFollowTheSuitesNotation) {
  SpeechGenerator speech(150.0);
  for (const std::string act :
       {"QUESTION:TIME", "greet()", "request(location(toilet))", "inform(time=now)",
        "greet(); request(location(toilet))", "affirm(),inform(beverage(tea))", "confirm(*)"}) {
    EXPECT_NO_THROW(speech.say(act, "hello", 0.0)) << act;
  }
  const std::pair<std::string, std::string> refused[] = {
      {"two words", "the character ' ' at offset 3"},
      {"greet(", "an unclosed '(' at offset 6"},
      {"greet())", "a ')' without its '(' at offset 7"},
      {"greet();", "no act after the last separator at offset 8"},
      {"greet();  bye()", "an act that does not start with a letter at offset 9"},
      {"(x)", "an act that does not start with a letter at offset 0"},
      {"say\"hi\"", "the character '\"' at offset 3"},
      {"tab\x7f", "expected no control characters, got byte 0x7f at offset 3"},
  };
  for (const auto& [act, why] : refused) {
    try {
      speech.say(act, "hello", 1.0);
      ADD_FAILURE() << "accepted '" << act << "'";
    } catch (const core::RequestError& e) {
      EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
    }
  }
  EXPECT_EQ(speech.act(), "confirm(*)");  // the refused acts left the last one alone
}

}  // namespace
}  // namespace ari_social_sim::world
