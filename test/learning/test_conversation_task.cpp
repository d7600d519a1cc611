#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/learning/nav_env.hpp"
#include "ari_social_sim/navigation/mlp_policy.hpp"

namespace ari_social_sim::learning {
namespace {

// join_conversation without perception errors: the shipped join_group policy then joins nearly
// always, so that the runs below differ in when ARI speaks, not in whether it arrives.
std::shared_ptr<const NavEnvSetup> conversation_setup() {
  return NavEnvSetup::load(ARI_SOURCE_DIR,
                           std::string(ARI_SOURCE_DIR) + "/config/learning/join_conversation.yaml",
                           "{perception_errors: false}", "test options");
}

// The observation's conversation part: member heard, addressed, s since a member's line, ARI.
struct Talk {
  float heard, addressed, silence_s, ari_speaking;
};
Talk talk_of(const std::vector<float>& observation, const NavEnv& env) {
  const float* c = observation.data() + env.observation().size();
  return {c[0], c[1], c[2], c[3]};
}

// How a policy decides to speak from what it observes.
enum class Speaker { kAlways, kRule };

struct Played {
  std::vector<float> observations;
  std::vector<double> rewards;
  NavMetrics metrics;
};

// The shipped join_group policy drives; `speaker` decides speak. The rule (docs/learning.md):
// speak only after a pause of 0.5 s, to answer or, near the place in the group, to greet once.
Played play(NavEnv& env, navigation::MlpPolicy& driver, Speaker speaker, uint64_t seed) {
  Played run;
  std::vector<float> observation(env.observation_size());
  env.reset(seed, observation.data());
  bool greeted = false;
  while (!env.done()) {
    const auto drive = driver.act(observation.data());
    const Talk talk = talk_of(observation, env);
    const float goal_distance_m = observation[8];  // the goal part's last value (layout)
    const bool pause = talk.silence_s > 0.5f && talk.heard < 0.5f && talk.ari_speaking < 0.5f;
    const bool greet = !greeted && goal_distance_m < 0.5f;
    const bool speak = speaker == Speaker::kAlways || (pause && (talk.addressed > 0.5f || greet));
    greeted = greeted || (speak && greet);
    const float action[kConversationActionSize] = {
        static_cast<float>(drive[0]), static_cast<float>(drive[1]), static_cast<float>(drive[2]),
        speak ? 1.0f : 0.0f};
    const NavStepResult result = env.step(action, observation.data());
    run.observations.insert(run.observations.end(), observation.begin(), observation.end());
    run.rewards.push_back(result.reward);
  }
  run.metrics = env.metrics();
  return run;
}

class JoinConversation : public ::testing::Test {
 protected:
  std::shared_ptr<const NavEnvSetup> setup_ = conversation_setup();
  navigation::MlpPolicy driver_ = navigation::MlpPolicy::load_file(
      std::string(ARI_SOURCE_DIR) + "/config/policies/join_group.yaml");
};

TEST_F(JoinConversation, ActionAndObservationGainTheConversationParts) {
  NavEnv env(setup_);
  EXPECT_EQ(env.action_size(), 4);
  EXPECT_EQ(env.observation_size(), env.observation().size() + 4);
  EXPECT_EQ(env.observation_fields().back().name, "conversation");
  NavEnv group(NavEnvSetup::load(ARI_SOURCE_DIR,
                                 std::string(ARI_SOURCE_DIR) + "/config/learning/join_group.yaml",
                                 "", "test options"));
  EXPECT_EQ(group.action_size(), 3);
  EXPECT_EQ(group.observation_size(), group.observation().size());
}

TEST_F(JoinConversation, TheSameSeedGivesTheSameEpisode) {
  NavEnv a(setup_), b(setup_);
  const Played first = play(a, driver_, Speaker::kRule, 4);
  const Played second = play(b, driver_, Speaker::kRule, 4);
  ASSERT_EQ(first.observations.size(), second.observations.size());
  EXPECT_EQ(0, std::memcmp(first.observations.data(), second.observations.data(),
                           first.observations.size() * sizeof(float)));
  EXPECT_EQ(first.rewards, second.rewards);
}

TEST_F(JoinConversation, SpeakingAllTheTimeInterruptsAndTheRuleDoesNot) {
  NavEnv env(setup_);
  int always = 0, rule = 0, rule_successes = 0;
  for (uint64_t seed : {1, 2, 3}) {
    always += play(env, driver_, Speaker::kAlways, seed).metrics.conversation->interruptions;
    const ConversationTaskMetrics c =
        *play(env, driver_, Speaker::kRule, seed).metrics.conversation;
    rule += c.interruptions;
    rule_successes += c.success ? 1 : 0;
    EXPECT_EQ(c.group_talk.ari_interruptions, 0) << "seed " << seed;
  }
  EXPECT_GE(always, 3);  // at least one per episode
  EXPECT_LE(rule, 1);
  EXPECT_GE(rule_successes, 2);
}

TEST_F(JoinConversation, MetricsAreFiniteAndCountTheConversation) {
  NavEnv env(setup_);
  const Played run = play(env, driver_, Speaker::kRule, 2);
  ASSERT_TRUE(run.metrics.conversation.has_value());
  const ConversationTaskMetrics& c = *run.metrics.conversation;
  const world::ConversationFigures& talk = c.group_talk;
  for (double value : {talk.overlap_share, talk.listener_gaze_at_speaker, talk.ari_floor_share,
                       talk.ari_addressed_after_s, c.answer_delay_s}) {
    EXPECT_TRUE(std::isfinite(value));
  }
  EXPECT_GT(talk.turn_transitions, 0);  // the members talked
  EXPECT_GT(c.ari_lines, 0);
  EXPECT_GE(talk.overlap_share, 0.0);
  EXPECT_LE(talk.overlap_share, 1.0);
}

TEST_F(JoinConversation, ANonFiniteSpeakIsRefusedByName) {
  NavEnv env(setup_);
  std::vector<float> observation(env.observation_size());
  env.reset(1, observation.data());
  const float bad[kConversationActionSize] = {0.0f, 0.0f, 0.0f, NAN};
  try {
    env.step(bad, observation.data());
    FAIL() << "a NaN speak was taken";
  } catch (const core::RequestError& e) {
    EXPECT_NE(std::string(e.what()).find("action[3] (speak)"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace ari_social_sim::learning
