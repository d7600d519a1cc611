#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/learning/nav_env.hpp"
#include "ari_social_sim/learning/vector_nav_env.hpp"

namespace ari_social_sim::learning {
namespace {

std::shared_ptr<const NavEnvSetup> setup(const std::string& task, const std::string& overrides) {
  return NavEnvSetup::load(ARI_SOURCE_DIR,
                           std::string(ARI_SOURCE_DIR) + "/config/learning/" + task + ".yaml",
                           overrides, "test options");
}

// A fixed, varied action sequence (no randomness in the test itself).
std::array<float, kActionSize> action_at(int step) {
  return {0.4f + 0.3f * static_cast<float>(std::sin(0.1 * step)),
          0.8f * static_cast<float>(std::cos(0.07 * step)), 0.5f};
}

struct Trace {
  std::vector<float> observations;
  std::vector<double> rewards;
  std::vector<int> ends;
};

Trace run(NavEnv& env, uint64_t seed, int steps) {
  Trace trace;
  std::vector<float> observation(env.observation_size());
  env.reset(seed, observation.data());
  trace.observations = observation;
  for (int i = 0; i < steps && !env.done(); ++i) {
    const auto action = action_at(i);
    const NavStepResult r = env.step(action.data(), observation.data());
    trace.observations.insert(trace.observations.end(), observation.begin(), observation.end());
    trace.rewards.push_back(r.reward);
    trace.ends.push_back(r.terminated * 2 + r.truncated);
  }
  return trace;
}

TEST(NavEnv, TheSameSeedGivesTheSameEpisodeBitForBit) {
  const auto s = setup("join_group", "{walkers: 3}");
  NavEnv a(s), b(s);
  const Trace first = run(a, 42, 300);
  const Trace second = run(b, 42, 300);
  ASSERT_EQ(first.observations.size(), second.observations.size());
  EXPECT_EQ(0, std::memcmp(first.observations.data(), second.observations.data(),
                           first.observations.size() * sizeof(float)));
  EXPECT_EQ(first.rewards, second.rewards);
  EXPECT_EQ(first.ends, second.ends);
  // Another seed is another episode.
  const Trace other = run(a, 43, 10);
  EXPECT_NE(0, std::memcmp(first.observations.data(), other.observations.data(),
                           a.observation_size() * sizeof(float)));
}

TEST(NavEnv, ActionsAreClippedToAriLimitsAndNonFiniteOnesRefusedByName) {
  NavEnv env(setup("go_to_pose", "{terminate_on_collision: false}"));
  std::vector<float> observation(env.observation_size());
  env.reset(5, observation.data());
  const float fast[kActionSize] = {50.0f, 0.0f, 9.0f};
  double fastest = 0.0;
  for (int i = 0; i < 60 && !env.done(); ++i) {
    env.step(fast, observation.data());
    fastest = std::max(fastest, static_cast<double>(observation[0]));
  }
  EXPECT_LE(fastest, 1.0 + 1e-6);  // ARI's max_linear
  EXPECT_GT(fastest, 0.9);
  EXPECT_NEAR(observation[2], 1.309, 0.01);  // head pan at its limit
  env.reset(5, observation.data());
  const float bad[kActionSize] = {0.1f, NAN, 0.0f};
  try {
    env.step(bad, observation.data());
    FAIL() << "a NaN action was taken";
  } catch (const core::RequestError& e) {
    EXPECT_NE(std::string(e.what()).find("action[1] (angular)"), std::string::npos) << e.what();
  }
}

TEST(NavEnv, EpisodesAreTruncatedAtTheTimeLimitAndEndOnArrival) {
  NavEnv env(setup("join_group", "{time_limit: 2.0, perception_errors: false}"));
  std::vector<float> observation(env.observation_size());
  env.reset(3, observation.data());
  const float still[kActionSize] = {0.0f, 0.0f, 0.0f};
  int steps = 0;
  NavStepResult r;
  while (!env.done()) {
    r = env.step(still, observation.data());
    ++steps;
  }
  EXPECT_EQ(steps, 40);  // 2 s of 0.05 s steps
  EXPECT_TRUE(r.truncated);
  EXPECT_FALSE(r.terminated);
  EXPECT_THROW(env.step(still, observation.data()), core::RequestError);

  // Driving to the true goal with a simple controller arrives: terminated, the arrival reward.
  NavEnv driven(setup("join_group", "{perception_errors: false, terminate_on_collision: false}"));
  driven.reset(3, observation.data());
  double total = 0.0;
  while (!driven.done()) {
    const auto& goal = driven.true_goal()->pose;
    const core::Pose2 ari = driven.simulation().ari()->pose();
    const Eigen::Vector2d to = goal.position - ari.position;
    const double bearing = core::angle_difference(std::atan2(to.y(), to.x()), ari.theta);
    const bool near = to.norm() < 0.1;
    const double turn = near ? core::angle_difference(goal.theta, ari.theta) : bearing;
    const float action[kActionSize] = {
        static_cast<float>(near || std::abs(bearing) > 0.5 ? 0.0 : std::min(0.5, to.norm())),
        static_cast<float>(std::clamp(2.0 * turn, -1.0, 1.0)), 0.0f};
    r = driven.step(action, observation.data());
    total += r.reward;
  }
  EXPECT_TRUE(r.terminated);
  EXPECT_TRUE(driven.metrics().arrived);
  EXPECT_GT(r.reward, 9.0);  // arrival's 10, less the step's time
  EXPECT_GT(driven.metrics().path_length_m, 1.0);
  EXPECT_GE(driven.metrics().gcff_includes_ari, 0);
}

TEST(VectorNavEnv, MatchesSingleEnvironmentsForAnyThreadCount) {
  const auto s = setup("join_group", "{walkers: 2, time_limit: 3.0}");
  const int n = 4, steps = 80;
  std::vector<std::vector<float>> results;
  for (int threads : {1, 2, 3}) {
    VectorNavEnv vec(s, n, threads);
    const size_t size = vec.observation_size();
    std::vector<float> obs(n * size), finals(n * size), all;
    std::vector<double> rewards(n);
    bool term[n], trunc[n];
    vec.reset(100, obs.data());
    for (int t = 0; t < steps; ++t) {
      std::vector<float> actions;
      for (int i = 0; i < n; ++i) {
        const auto a = action_at(t + 7 * i);
        actions.insert(actions.end(), a.begin(), a.end());
      }
      vec.step(actions.data(), {obs.data(), rewards.data(), term, trunc, finals.data()});
      all.insert(all.end(), obs.begin(), obs.end());
      for (double r : rewards) {
        all.push_back(static_cast<float>(r));
      }
    }
    results.push_back(all);
  }
  EXPECT_EQ(results[0], results[1]);
  EXPECT_EQ(results[0], results[2]);

  // Environment 2 plays seed 102 first, as a single environment would.
  NavEnv single(s);
  std::vector<float> first(single.observation_size()), row(single.observation_size());
  single.reset(102, first.data());
  VectorNavEnv vec(s, n, 2);
  std::vector<float> obs(n * single.observation_size());
  vec.reset(100, obs.data());
  EXPECT_EQ(0, std::memcmp(first.data(), obs.data() + 2 * single.observation_size(),
                           first.size() * sizeof(float)));
}

TEST(NavEnvSetup, OptionsAreCheckedByName) {
  try {
    setup("join_group", "{rewards: {arival: 3}}");
    FAIL();
  } catch (const core::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("arival"), std::string::npos) << e.what();
  }
  EXPECT_THROW(setup("join_group", "{walkers: -1}"), core::ConfigError);
  EXPECT_THROW(setup("join_group", "{observation: {nearest_people: 1000}}"), core::ConfigError);
}

}  // namespace
}  // namespace ari_social_sim::learning
