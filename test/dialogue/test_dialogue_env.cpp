#include <gtest/gtest.h>

#include "ari_social_sim/dialogue/dialogue_env.hpp"
#include "ari_social_sim/dialogue/rule_policy.hpp"
#include "test_helpers.hpp"

namespace ari_social_sim::dialogue {
namespace {

class DialogueEnvTest : public ::testing::Test {
 protected:
  DialogueEnvTest()
      : setup_(DialogueSetup::create(DialogueConfig::defaults(ARI_DIALOGUE_CONFIG_DIR))) {}
  std::unique_ptr<DialogueSetup> setup_;
};

TEST_F(DialogueEnvTest, SilentRobotIsTruncatedAtTheCap) {
  DialogueConfig config = DialogueConfig::defaults(ARI_DIALOGUE_CONFIG_DIR);
  config.reward.max_turns = 5;
  const auto setup = DialogueSetup::create(config);
  DialogueEnv env(*setup);
  env.reset(3);
  double total = 0;
  StepResult result;
  for (int turn = 1; turn <= 5; ++turn) {
    result = env.step(RobotAction{});
    total += result.reward;
    ASSERT_FALSE(result.terminated) << turn;
    EXPECT_EQ(result.truncated, turn == 5);
  }
  // Nobody is ever answered: 5 turns x -1, then -40 for failure = -45.
  EXPECT_DOUBLE_EQ(total, -45.0);
  EXPECT_FALSE(result.info.complete);
  EXPECT_EQ(result.info.robot_turns, 5);
  EXPECT_EQ(result.info.patience.size(), 2u);
  EXPECT_TRUE(env.episode_over());
}

TEST_F(DialogueEnvTest, CurrentInfoAfterResetHasGoalsAndPatience) {
  DialogueEnv env(*setup_);
  env.reset(3);
  const StepInfo info = env.current_info();
  EXPECT_EQ(info.robot_turns, 0);
  EXPECT_EQ(info.utterances, static_cast<int>(env.transcript().size()));
  EXPECT_EQ(info.goals.size(), env.users().agenda().goals().size());
  EXPECT_GE(info.goals.size(), 1u);
  // One patience per human, each in [min_patience, max_patience] = [3, 5].
  ASSERT_EQ(info.patience.size(), 2u);
  for (int p : info.patience) {
    EXPECT_GE(p, 3);
    EXPECT_LE(p, 5);
  }
  EXPECT_FALSE(info.complete);
}

TEST_F(DialogueEnvTest, RulePolicyEpisodesEndAndPayTheBonus) {
  DialogueEnv env(*setup_);
  RulePolicy policy(setup_->domain);
  int successes = 0;
  const int episodes = 200;
  for (int seed = 0; seed < episodes; ++seed) {
    policy.reset();
    Observation observation = env.reset(seed);
    double total = 0;
    StepResult result;
    do {
      result = env.step(policy.act(observation));
      observation = result.observation;
      total += result.reward;
    } while (!result.terminated && !result.truncated);
    // Reward = -turns + 80 on success, -turns - 40 otherwise.
    const double turns = result.info.robot_turns;
    EXPECT_DOUBLE_EQ(total, result.info.success ? 80.0 - turns : -40.0 - turns);
    successes += result.info.success ? 1 : 0;
    EXPECT_FALSE(result.info.goals.empty());
  }
  // docs/dialogue.md: about 80 % success over 1000 dialogues.
  EXPECT_GT(successes, episodes * 0.65);
}

TEST_F(DialogueEnvTest, SameSeedSameEpisode) {
  DialogueEnv a(*setup_);
  DialogueEnv b(*setup_);
  RulePolicy pa(setup_->domain);
  RulePolicy pb(setup_->domain);
  Observation oa = a.reset(42);
  Observation ob = b.reset(42);
  for (int i = 0; i < 10 && !a.episode_over(); ++i) {
    oa = a.step(pa.act(oa)).observation;
    ob = b.step(pb.act(ob)).observation;
  }
  ASSERT_EQ(a.transcript().size(), b.transcript().size());
  for (size_t i = 0; i < a.transcript().size(); ++i) {
    EXPECT_EQ(a.transcript()[i].text, b.transcript()[i].text);
    EXPECT_EQ(a.transcript()[i].heard.text, b.transcript()[i].heard.text);
  }
}

}  // namespace
}  // namespace ari_social_sim::dialogue
