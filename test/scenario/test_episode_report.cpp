#include <gtest/gtest.h>

#include "ari_social_sim/scenario/episode_report.hpp"

namespace ari_social_sim::scenario {
namespace {

const std::string kSource = ARI_SOURCE_DIR;

// Accepts every command.
class NoCommands : public Commands {
 public:
  void say(const AgentRef&, const std::string&, const std::string&) override {}
  void set_human_goal(model::ObjectId, const core::Pose2&) override {}
  void navigate(const core::Pose2&) override {}
  void approach(const std::string&, bool) override {}
  void fail_navigation(const std::string&) override {}
  void cancel_navigation() override {}
  void add_human(const world::HumanSpec&) override {}
  void remove_human(model::ObjectId) override {}
  void create_group(const world::GroupSpec&) override {}
  void create_walking_group(const world::WalkingGroupSpec&) override {}
  void add_group_members(model::ObjectId, const std::vector<model::ObjectId>&) override {}
  void set_group_centre(model::ObjectId, const Eigen::Vector2d&) override {}
  void set_group_arrangement(model::ObjectId, model::Arrangement, std::optional<double>) override {}
  void leave_group(model::ObjectId) override {}
  void set_posture(model::ObjectId, world::Posture) override {}
};

// test/integration/scenario_humans.yaml from 2 s of sim time to 5.5 s: Ana walks (state walk).
class HumansReport : public ::testing::Test {
 protected:
  void play_to_walk() {
    Observations observations;
    world::HumanSnapshot ana;
    ana.id = 10;
    ana.name = "Ana";
    ana.pose.position = {1.0, 1.0};
    observations.world.humans = {ana};
    for (double t : {2.0, 5.5}) {
      observations.world.time_s = t;
      runner.update(observations, commands);
    }
  }

  Scenario scenario = load_scenario_file(kSource + "/test/integration/scenario_humans.yaml");
  ScriptRunner runner{scenario, 1};
  NoCommands commands;
  EpisodeMetrics metrics;
};

TEST_F(HumansReport, AnInterruptedRunSaysWhereItWas) {
  play_to_walk();
  runner.interrupt("SIGINT");
  const std::string report = format_report(scenario.name, runner, metrics);
  EXPECT_NE(report.find("states: walk 0.00 s\n"), std::string::npos) << report;
  EXPECT_NE(report.find("outcome: interrupted in state walk after 3.50 s (SIGINT)\n"),
            std::string::npos)
      << report;
}

TEST_F(HumansReport, AnAbortedRunGivesTheReason) {
  play_to_walk();
  runner.abort("no /sim/world_state for 3 s (world_node gone?) while in state walk");
  EXPECT_NE(format_report(scenario.name, runner, metrics)
                .find("outcome: failure after 3.50 s in state walk: no /sim/world_state for 3 s "
                      "(world_node gone?) while in state walk\n"),
            std::string::npos);
}

TEST_F(HumansReport, ARunStoppedBeforeItsFirstTickSaysSo) {
  runner.abort("wall-time limit of 240 s reached while waiting for the /tts action server");
  const std::string report = format_report(scenario.name, runner, metrics);
  EXPECT_NE(report.find("states:\n"), std::string::npos) << report;
  EXPECT_NE(report.find("outcome: failure before the script started: wall-time limit of 240 s "
                        "reached while waiting for the /tts action server\n"),
            std::string::npos)
      << report;
  ScriptRunner interrupted{scenario, 1};
  interrupted.interrupt("SIGINT");
  EXPECT_NE(format_report(scenario.name, interrupted, metrics)
                .find("outcome: interrupted before the script started (SIGINT)\n"),
            std::string::npos);
}

}  // namespace
}  // namespace ari_social_sim::scenario
