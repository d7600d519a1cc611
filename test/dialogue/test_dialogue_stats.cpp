#include <gtest/gtest.h>

#include "ari_social_sim/dialogue/dialogue_stats.hpp"

namespace ari_social_sim::dialogue {
namespace {

TEST(DialogueStats, JsDivergenceBounds) {
  const Distribution p{{"a", 0.5}, {"b", 0.5}};
  const Distribution q{{"c", 1.0}};
  EXPECT_DOUBLE_EQ(js_divergence(p, p), 0.0);
  // Disjoint supports: 1 bit.
  EXPECT_NEAR(js_divergence(p, q), 1.0, 1e-12);
  // P = (1, 0), Q = (0.5, 0.5): M = (0.75, 0.25);
  // JS = 0.5 (1 log2(1/0.75)) + 0.5 (0.5 log2(0.5/0.75) + 0.5 log2(0.5/0.25)) = 0.3113.
  EXPECT_NEAR(js_divergence({{"a", 1.0}}, p), 0.311278, 1e-6);
}

TEST(DialogueStats, HeuristicAndCounts) {
  const CorpusDialogue d = parse_mpgt_dialogue(
      "LP: Shall we ask? # suggest(requesting(food))\n"
      "RC: Yes. # affirm()\n"
      "RC: ARI, where can we eat? # request(food)\n"
      "ARI: Cafeteria. # inform(food)\n",
      "t");
  EXPECT_TRUE(is_human_to_human(d, 0));   // next speaker is the other human
  EXPECT_FALSE(is_human_to_human(d, 1));  // same speaker next
  EXPECT_FALSE(is_human_to_human(d, 2));  // ARI next
  const DialogueStats stats = compute_stats({d});
  EXPECT_EQ(stats.utterances, 4u);
  EXPECT_EQ(stats.human_utterances, 3u);
  EXPECT_DOUBLE_EQ(stats.human_to_human_share, 0.25);  // 1 of 4
  EXPECT_DOUBLE_EQ(stats.first_intents.at("request"), 1.0 / 3.0);
  EXPECT_EQ(stats.length_quantile(0.5), 4u);
}

TEST(DialogueStats, MpgtHumanToHumanShare) {
  const MpgtCorpus corpus = load_mpgt_corpus(ARI_MPGT_DIR);
  const DialogueStats stats = compute_stats(corpus.dialogues);
  // 174 of 768 utterances.
  EXPECT_NEAR(stats.human_to_human_share, 174.0 / 768.0, 1e-12);
  EXPECT_NEAR(stats.mean_length(), 768.0 / 29.0, 1e-12);
}

}  // namespace
}  // namespace ari_social_sim::dialogue
