#include <gtest/gtest.h>

#include "ari_social_sim/dialogue/goal.hpp"

namespace ari_social_sim::dialogue {
namespace {

TEST(Goal, ParsesMpgtLabelsWithSeatCodes) {
  int skipped = 0;
  const auto labels = parse_mpgt_goal_labels(
      "G(LP+RC, go-to(lifts)); AG(RC, get-info(cafe(opening_times)))", &skipped);
  ASSERT_EQ(labels.size(), 2u);
  EXPECT_EQ(skipped, 0);
  EXPECT_EQ(labels[0].kind, GoalLabelKind::kStated);
  EXPECT_EQ(labels[0].goal.owners, (std::vector<std::string>{"patient", "companion"}));
  EXPECT_TRUE(labels[0].goal.is_joint());
  EXPECT_EQ(labels[0].to_string(), "G(patient+companion, go-to(lifts))");
  EXPECT_EQ(labels[1].kind, GoalLabelKind::kAnswered);
  EXPECT_EQ(labels[1].to_string(), "AG(companion, get-info(cafe(opening_times)))");
}

TEST(Goal, EmptyObjectAndCorpusTypos) {
  int skipped = 0;
  // `LC_RP` and `go_to` occur once each in MPGT; a missing `)` too (convo7).
  const auto labels = parse_mpgt_goal_labels(
      "CG(LC_RP, eat()); G(RC, go_to(ground_floor)); G(LP, get-info(doctor(room))", &skipped);
  ASSERT_EQ(labels.size(), 3u);
  EXPECT_EQ(labels[0].to_string(), "CG(companion+patient, eat())");
  EXPECT_EQ(labels[1].goal.predicate, "go-to");
  EXPECT_EQ(labels[2].goal.object, (std::vector<std::string>{"doctor", "room"}));
  EXPECT_EQ(skipped, 0);
}

TEST(Goal, UnreadableLabelsAreSkippedAndCounted) {
  int skipped = 0;
  // Unknown owner code, unknown label kind: 2 skipped, 1 kept.
  const auto labels =
      parse_mpgt_goal_labels("G(XX, eat()); BG(LP, eat()); G(LP, drink(coffee))", &skipped);
  EXPECT_EQ(labels.size(), 1u);
  EXPECT_EQ(skipped, 2);
}

TEST(Goal, SameTargetIgnoresOwners) {
  Goal a{{"patient"}, "go-to", {"toilet"}};
  Goal b{{"companion"}, "go-to", {"toilet"}};
  Goal c{{"companion"}, "go-to", {"cafe"}};
  EXPECT_TRUE(a.same_target(b));
  EXPECT_FALSE(a.same_target(c));
  EXPECT_EQ(mpgt_role("RP"), "patient");
  EXPECT_EQ(mpgt_role("XX"), "");
}

}  // namespace
}  // namespace ari_social_sim::dialogue
