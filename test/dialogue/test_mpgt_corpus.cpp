#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>

#include "../common/data_sets.hpp"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/dialogue/mpgt_corpus.hpp"
#include "test_helpers.hpp"

namespace ari_social_sim::dialogue {
namespace {

TEST(MpgtCorpus, ParsesTextActsAndGoals) {
  const CorpusDialogue dialogue = parse_mpgt_dialogue(
      "LP: Hello ARI. # greet()\n"
      "RC: Where is it? # request(location(cafe)) @ G(RC, go-to(cafe))\n"
      "RP: Does that suit you? @ AG(LC, drink(coffee))\n"
      "\n"
      "LC: Mind the step there.\n",
      "inline");
  ASSERT_EQ(dialogue.utterances.size(), 4u);
  EXPECT_EQ(dialogue.utterances[0].text, "Hello ARI.");
  EXPECT_EQ(dialogue.utterances[1].role, "companion");
  EXPECT_EQ(dialogue.utterances[1].goals[0].to_string(), "G(companion, go-to(cafe))");
  EXPECT_EQ(dialogue.utterances[2].first_intent(), "none");  // goal label but no act
  EXPECT_EQ(dialogue.utterances[2].goals.size(), 1u);
  EXPECT_EQ(dialogue.utterances[3].text, "Mind the step there.");
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
  ARI_SKIP_WITHOUT_DATA_SET(kMpgtDataSet);
  const MpgtCorpus corpus = load_mpgt_corpus(core::data_set_dir(kMpgtDataSet));
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

using testing::ScopedEnvironment;

TEST(MpgtCorpus, OnlyANonEmptyEnvironmentVariablePointsAtTheCorpus) {
  {
    const ScopedEnvironment corpus("ARI_MPGT_DIR", "/data/mpgt");
    EXPECT_EQ(mpgt_dir_from_environment(), "/data/mpgt");
  }
  {
    const ScopedEnvironment corpus("ARI_MPGT_DIR", "");  // set but empty: not a folder
    EXPECT_EQ(mpgt_dir_from_environment(), "");
  }
  const ScopedEnvironment corpus("ARI_MPGT_DIR", std::nullopt);
  EXPECT_EQ(mpgt_dir_from_environment(), "");
}

TEST(MpgtCorpus, ToolsLookForTheCorpusInOrderAndSayHowToGetIt) {
  namespace fs = std::filesystem;
  const std::string data = ::testing::TempDir() + "mpgt_tool_lookup";
  fs::remove_all(data);
  fs::create_directories(data);
  const ScopedEnvironment data_dir("ARI_DATA_DIR", data);
  const ScopedEnvironment unset("ARI_MPGT_DIR", std::nullopt);
  // Nothing anywhere: what needs it, and the command that fetches it.
  testing::expect_config_error(
      [] { required_mpgt_dir("", "--compare"); },
      {"--compare needs the MPGT corpus", "no --corpus DIR, ARI_MPGT_DIR not set",
       data + "/dialogue/mpgt", "scripts/fetch_data.sh"});
  // The fetched data set.
  fs::create_directories(data + "/dialogue/mpgt");
  std::ofstream(data + "/dialogue/mpgt/convo1.txt") << "ARI: Hello. # greet()\n";
  EXPECT_EQ(required_mpgt_dir("", "--compare"), data + "/dialogue/mpgt");
  // The environment before the data set, the option before both; each checked by its name.
  {
    const ScopedEnvironment corpus("ARI_MPGT_DIR", data);
    EXPECT_EQ(required_mpgt_dir("", "--compare"), data);
    EXPECT_EQ(required_mpgt_dir(data + "/dialogue", "--compare"), data + "/dialogue");
  }
  {
    const ScopedEnvironment corpus("ARI_MPGT_DIR", data + "/none");
    testing::expect_config_error([] { required_mpgt_dir("", "--compare"); },
                                 {"$ARI_MPGT_DIR: " + data + "/none: expected a directory"});
  }
  testing::expect_config_error([&] { required_mpgt_dir(data + "/none", "--compare"); },
                               {"--corpus: " + data + "/none: expected a directory"});
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
