#include <gtest/gtest.h>

#include "ari_social_sim/dialogue/agenda.hpp"
#include "test_helpers.hpp"

namespace ari_social_sim::dialogue {
namespace {

using testing::config_path;

TEST(Agenda, SamplesCountsAndJointShare) {
  const Domain domain = Domain::load(config_path("hospital_domain.yaml"));
  GoalCountModel counts;
  counts.counts = {2, 4};
  counts.probabilities = {0.5, 0.5};
  counts.joint_share = 0.25;
  core::Rng rng(9);
  double goals = 0;
  double joint = 0;
  const int n = 4000;
  for (int i = 0; i < n; ++i) {
    const Agenda agenda = Agenda::sample(domain, counts, {"patient", "companion"}, rng);
    for (const TrackedGoal& g : agenda.goals()) {
      goals += 1;
      joint += g.goal.is_joint() ? 1 : 0;
    }
  }
  EXPECT_NEAR(goals / n, 3.0, 0.05);  // (2 + 4) / 2
  EXPECT_NEAR(joint / goals, 0.25, 0.015);
}

TEST(Agenda, OwnAgendaSharedPoolAndDoneness) {
  Agenda agenda({TrackedGoal{Goal{{"patient"}, "go-to", {"toilet"}}},
                 TrackedGoal{Goal{{"patient", "companion"}, "eat", {}}},
                 TrackedGoal{Goal{{"companion"}, "drink", {"coffee"}}}});
  core::Rng rng(1);
  // The companion can raise the joint goal (1) or its own (2), never the patient's (0).
  for (int i = 0; i < 20; ++i) {
    const int next = agenda.next_waiting("companion", rng);
    EXPECT_TRUE(next == 1 || next == 2) << next;
  }
  agenda.mark_stated(0);
  agenda.mark_stated(1);
  EXPECT_EQ(agenda.open_goal("patient"), 1);  // the most recent
  EXPECT_EQ(agenda.focus(), 1);
  agenda.goals()[1].status = GoalStatus::kResolved;
  EXPECT_EQ(agenda.closable("companion"), std::vector<int>{1});
  agenda.goals()[0].status = GoalStatus::kClosed;
  EXPECT_TRUE(agenda.done("patient"));
  EXPECT_FALSE(agenda.done("companion"));  // drink(coffee) still waiting
  EXPECT_FALSE(agenda.all_done());
}

}  // namespace
}  // namespace ari_social_sim::dialogue
