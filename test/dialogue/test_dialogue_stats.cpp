#include <gtest/gtest.h>

#include "../common/data_sets.hpp"
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
  // No goal labels; the last three utterances hold no bye() and no thank().
  EXPECT_DOUBLE_EQ(stats.mean_goal_targets, 0.0);
  EXPECT_DOUBLE_EQ(stats.bye_closing_share, 0.0);
  EXPECT_DOUBLE_EQ(stats.thank_closing_share, 0.0);
}

TEST(DialogueStats, GoalsAndClosings) {
  const CorpusDialogue closing = parse_mpgt_dialogue(
      "LP: Where is the cafe? # request(location(cafe)) @ G(LP, go-to(cafe))\n"
      "ARI: Down there. # inform(location(cafe)) @ AG(LP, go-to(cafe))\n"
      "RC: And coffee? # request(beverage(coffee)) @ G(RC, drink(coffee))\n"
      "ARI: There too. # inform(beverage(coffee))\n"
      "LP: Thanks. # thank()\n"
      "ARI: Bye. # bye()\n",
      "closing");
  // bye() only before the last three utterances: not a closing.
  const CorpusDialogue early_bye =
      parse_mpgt_dialogue("LP: Bye. # bye()\nRC: Hmm.\nLP: Hmm.\nRC: Hmm.\n", "early");
  const DialogueStats stats = compute_stats({closing, early_bye});
  EXPECT_DOUBLE_EQ(stats.mean_goal_targets, (2.0 + 0.0) / 2.0);  // go-to(cafe), drink(coffee)
  EXPECT_DOUBLE_EQ(stats.bye_closing_share, 0.5);
  EXPECT_DOUBLE_EQ(stats.thank_closing_share, 0.5);
}

TEST(DialogueStats, VarietyCountsDistinctTextsPerSideAndFirstAct) {
  const CorpusDialogue d = parse_mpgt_dialogue(
      "LP: Thanks. # thank()\n"
      "RC: Thanks. # thank()\n"
      "LP: Thank you. # thank()\n"
      "ARI: Thanks. # thank()\n"
      "RC: Hmm.\n"
      "LP: Where is it? # request(location(cafe)); thank()\n",
      "t");
  const std::vector<ActVariety> variety = act_variety({d, d});
  // Humans first, most utterances first: thank() 6 (2 texts), then none and request 2 (1 text)
  // in name order; ARI's thank() 2 (1 text).
  ASSERT_EQ(variety.size(), 4u);
  EXPECT_FALSE(variety[0].robot);
  EXPECT_EQ(variety[0].first_act, "thank()");
  EXPECT_EQ(variety[0].utterances, 6u);
  EXPECT_EQ(variety[0].distinct_texts, 2u);
  EXPECT_DOUBLE_EQ(variety[0].ratio(), 2.0 / 6.0);
  EXPECT_EQ(variety[1].first_act, "none");
  EXPECT_EQ(variety[2].first_act, "request(location(cafe))");
  EXPECT_DOUBLE_EQ(variety[2].ratio(), 0.5);
  EXPECT_TRUE(variety[3].robot);
  EXPECT_EQ(variety[3].utterances, 2u);
  EXPECT_EQ(variety[3].distinct_texts, 1u);
}

TEST(DialogueStats, MpgtHumanToHumanShare) {
  ARI_SKIP_WITHOUT_DATA_SET(kMpgtDataSet);
  const MpgtCorpus corpus = load_mpgt_corpus(core::data_set_dir(kMpgtDataSet));
  const DialogueStats stats = compute_stats(corpus.dialogues);
  // 174 of 768 utterances.
  EXPECT_NEAR(stats.human_to_human_share, 174.0 / 768.0, 1e-12);
  EXPECT_NEAR(stats.mean_length(), 768.0 / 29.0, 1e-12);
}

}  // namespace
}  // namespace ari_social_sim::dialogue
