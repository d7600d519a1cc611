#include <gtest/gtest.h>

#include "ari_social_sim/dialogue/reward.hpp"
#include "test_helpers.hpp"

namespace ari_social_sim::dialogue {
namespace {

TEST(Reward, CompleteAndSuccessAreJudgedSeparately) {
  Agenda agenda(
      {TrackedGoal{Goal{{"patient"}, "go-to", {"toilet"}}, GoalStatus::kClosed, 1, 0, true},
       TrackedGoal{Goal{{"companion"}, "go-to", {"cafe"}}, GoalStatus::kResolved, 1, 1, false}});
  // Every goal resolved, one with a wrong cant-help: complete, not success.
  DialogueOutcome outcome = judge(agenda, false);
  EXPECT_TRUE(outcome.complete);
  EXPECT_FALSE(outcome.success);
  agenda.goals()[1].satisfied = true;
  EXPECT_TRUE(judge(agenda, false).success);
  EXPECT_FALSE(judge(agenda, true).complete);  // truncated
  agenda.goals()[1].status = GoalStatus::kFailed;
  EXPECT_FALSE(judge(agenda, false).complete);
}

TEST(Reward, StepRewardArithmetic) {
  const RewardConfig config;  // cap 40: +80 success, -40 failure, -1 a turn
  EXPECT_DOUBLE_EQ(step_reward(config, false, {}), -1.0);
  EXPECT_DOUBLE_EQ(step_reward(config, true, {true, true}), 79.0);    // -1 + 80
  EXPECT_DOUBLE_EQ(step_reward(config, true, {true, false}), -41.0);  // -1 - 40
  RewardConfig bad;
  bad.max_turns = 0;
  testing::expect_config_error([&] { bad.validate(); },
                               {"RewardConfig: max_turns", "> 0", "got 0"});
}

}  // namespace
}  // namespace ari_social_sim::dialogue
