#include <gtest/gtest.h>

#include <functional>

#include "ari_social_sim/dialogue/dialogue_runner.hpp"
#include "ari_social_sim/dialogue/json_lines.hpp"
#include "test_helpers.hpp"

namespace ari_social_sim::dialogue {
namespace {

// The JSON lines dialogue_corpus writes for `count` dialogues of `seed`.
std::string corpus_jsonl(const DialogueSetup& setup, uint64_t seed, int count) {
  DialogueEnv env(setup);
  RulePolicy policy(setup.domain);
  std::string out;
  for (int d = 0; d < count; ++d) {
    for (const Utterance& u : run_episode(env, policy, episode_seed(seed, d)).utterances) {
      out += utterance_json(d, u) + "\n";
    }
  }
  return out;
}

TEST(DialogueRunner, SameSeedSameBytesOtherSeedOtherBytes) {
  const auto setup = DialogueSetup::create(DialogueConfig::defaults(ARI_DIALOGUE_CONFIG_DIR));
  const std::string first = corpus_jsonl(*setup, 7, 50);
  // A second setup and environment, so no state can leak between the runs.
  const auto again = DialogueSetup::create(DialogueConfig::defaults(ARI_DIALOGUE_CONFIG_DIR));
  EXPECT_EQ(corpus_jsonl(*again, 7, 50), first);
  EXPECT_NE(corpus_jsonl(*setup, 8, 50), first);
  EXPECT_GT(first.size(), 10000u);
}

TEST(DialogueRunner, DialogueSeedsAreIndependentOfTheBatchSize) {
  const auto setup = DialogueSetup::create(DialogueConfig::defaults(ARI_DIALOGUE_CONFIG_DIR));
  const std::string ten = corpus_jsonl(*setup, 3, 10);
  const std::string five = corpus_jsonl(*setup, 3, 5);
  EXPECT_EQ(ten.substr(0, five.size()), five);
}

TEST(DialogueRunner, GroundTruthHumanToHumanShare) {
  EpisodeRecord episode;
  episode.utterances.resize(4);
  episode.utterances[0].speaker = kRobot;
  episode.utterances[0].addressees = {"patient"};
  episode.utterances[1].speaker = "patient";
  episode.utterances[1].addressees = {"companion"};
  episode.utterances[2].speaker = "companion";
  episode.utterances[2].addressees = {kRobot};
  episode.utterances[3].speaker = "patient";
  episode.utterances[3].addressees = {"companion"};
  EXPECT_DOUBLE_EQ(true_human_to_human_share({episode}), 0.5);  // 2 of 4
  EXPECT_EQ(to_corpus_dialogue(episode.utterances).utterances[1].role, "patient");
}

}  // namespace
}  // namespace ari_social_sim::dialogue
