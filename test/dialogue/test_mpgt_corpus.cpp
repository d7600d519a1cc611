#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <map>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/dialogue/mpgt_corpus.hpp"

namespace ari_social_sim::dialogue {
namespace {

TEST(MpgtCorpus, ParsesTextActsAndGoals) {
  const CorpusDialogue dialogue = parse_mpgt_dialogue(
      "LP: Hello ARI. # greet()\n"
      "RC: Where is it? # request(location(cafe)) @ G(RC, go-to(cafe))\n"
      "RP: Does that suit you? @ AG(LC, drink(coffee))\n"
      "\n"
      "LC: We'll walk slowly.\n",
      "inline");
  ASSERT_EQ(dialogue.utterances.size(), 4u);
  EXPECT_EQ(dialogue.utterances[0].text, "Hello ARI.");
  EXPECT_EQ(dialogue.utterances[1].role, "companion");
  EXPECT_EQ(dialogue.utterances[1].goals[0].to_string(), "G(companion, go-to(cafe))");
  EXPECT_EQ(dialogue.utterances[2].first_intent(), "none");  // goal label but no act
  EXPECT_EQ(dialogue.utterances[2].goals.size(), 1u);
  EXPECT_EQ(dialogue.utterances[3].text, "We'll walk slowly.");
}

TEST(MpgtCorpus, BadSpeakerNamesTheLine) {
  try {
    parse_mpgt_dialogue("LP: Hi. # greet()\nXY: Hi.\n", "c.txt");
    FAIL() << "no error";
  } catch (const core::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("c.txt:2"), std::string::npos) << e.what();
  }
}

TEST(MpgtCorpus, LoadsTheCorpusCounts) {
  const MpgtCorpus corpus = load_mpgt_corpus(ARI_MPGT_DIR);
  // MPGT: 29 conversations, 768 utterances, ARI 279, 6..82 per conversation.
  ASSERT_EQ(corpus.dialogues.size(), 29u);
  EXPECT_EQ(corpus.utterance_count(), 768u);
  std::map<std::string, int> by_speaker;
  std::map<std::string, int> intents;
  size_t shortest = 1000;
  size_t longest = 0;
  for (const auto& dialogue : corpus.dialogues) {
    shortest = std::min(shortest, dialogue.utterances.size());
    longest = std::max(longest, dialogue.utterances.size());
    for (const auto& u : dialogue.utterances) {
      ++by_speaker[u.speaker];
      for (const auto& act : u.acts) {
        ++intents[act.intent];
      }
    }
  }
  EXPECT_EQ(by_speaker["ARI"], 279);
  EXPECT_EQ(by_speaker["RC"], 155);
  EXPECT_EQ(by_speaker["LP"], 102);
  EXPECT_EQ(shortest, 6u);
  EXPECT_EQ(longest, 82u);
  // Act counts of section 2.1 (all speakers): thank 84, cant-help 57; request 225 and inform 114
  // there, one more each here: convo24 joins two requests and convo5 two informs with `,`, which we
  // split into two acts.
  EXPECT_EQ(intents["request"], 225 + 1);
  EXPECT_EQ(intents["inform"], 114 + 1);
  EXPECT_EQ(intents["thank"], 84);
  EXPECT_EQ(intents["cant-help"], 57);
  EXPECT_GT(corpus.act_repairs, 0);
}

TEST(MpgtCorpus, EnvironmentReplacesTheBuildTimeFolder) {
  const char* before = std::getenv("ARI_MPGT_DIR");
  const std::string saved = before != nullptr ? before : "";
  ASSERT_EQ(setenv("ARI_MPGT_DIR", "/data/mpgt", 1), 0);
  EXPECT_EQ(default_mpgt_dir(), "/data/mpgt");
  ASSERT_EQ(setenv("ARI_MPGT_DIR", "", 1), 0);  // set but empty: not a folder
  EXPECT_EQ(default_mpgt_dir(), ARI_MPGT_DIR);
  ASSERT_EQ(unsetenv("ARI_MPGT_DIR"), 0);
  EXPECT_EQ(default_mpgt_dir(), ARI_MPGT_DIR);
  if (before != nullptr) {
    setenv("ARI_MPGT_DIR", saved.c_str(), 1);
  }
}

TEST(MpgtCorpus, MissingDirectoryIsAConfigError) {
  EXPECT_THROW(load_mpgt_corpus("/nonexistent/mpgt"), core::ConfigError);
}

TEST(MpgtCorpus, ConversationThatIsNoFileIsAConfigError) {
  // A directory named like a conversation is refused by name, before anything is read.
  const std::string corpus = ::testing::TempDir() + "mpgt_with_a_directory";
  std::filesystem::create_directories(corpus + "/convo1.txt");
  try {
    load_mpgt_corpus(corpus);
    FAIL() << "accepted a directory as a conversation";
  } catch (const core::ConfigError& e) {
    EXPECT_EQ(std::string(e.what()),
              corpus + "/convo1.txt: expected an MPGT conversation, got a directory");
  }
}

}  // namespace
}  // namespace ari_social_sim::dialogue
