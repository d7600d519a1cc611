#pragma once

#include <string>

#include "ari_social_sim/core/config_fields.hpp"
#include "ari_social_sim/navigation/policy_observation.hpp"

namespace ari_social_sim::learning {

/// What a navigation environment asks of the policy.
enum class NavTask { kGoToPose, kApproachPerson, kJoinGroup, kScenario, kJoinConversation };

inline constexpr core::Choice<NavTask> kNavTaskNames[] = {
    {NavTask::kGoToPose, "go_to_pose"},
    {NavTask::kApproachPerson, "approach_person"},
    {NavTask::kJoinGroup, "join_group"},
    {NavTask::kScenario, "scenario"},
    {NavTask::kJoinConversation, "join_conversation"}};

/// The reward of a step is the sum of these terms (docs/learning.md). Signs are part of the
/// weights: a penalty has a negative weight, and 0 switches a term off.
struct RewardWeights {
  double progress{1.0};         // per metre the goal came closer (negative when it went away)
  double arrival{10.0};         // once, on arriving
  double collision{-10.0};      // per contact begun with a person or a wall or furniture
  double personal_space{-1.0};  // per second inside a personal space (those approached excepted)
  double ospace{-2.0};          // per entry into the o-space of a group not joined
  double smoothness{-0.01};     // per m/s and rad/s the command changed since the last step
  double time{-0.1};            // per second
  // join_conversation only, judged on the world's floor (GroupSnapshot::speaker):
  double interruption{-2.0};  // per line ARI begins while a member holds the floor
  double intrusion{-2.0};     // per entry into the group while a member holds the floor
  double answer{5.0};         // per answer begun within conversation.answer_window of a question

  template <class V>
  void visit(V& v) {
    v.field("progress", progress, "per metre the true goal came closer");
    v.field("arrival", arrival, "once, when the episode ends arrived");
    v.field("collision", collision, "per contact begun with a person, wall or furniture");
    v.field("personal_space", personal_space,
            "per second with ARI's footprint in someone's personal space (nav_benchmark's rule)");
    v.field("ospace", ospace, "per entry into the o-space of a group ARI is not joining");
    v.field("smoothness", smoothness, "per m/s plus rad/s of change between consecutive commands");
    v.field("time", time, "per second of the episode");
    v.field("interruption", interruption,
            "join_conversation: per line ARI begins while a member of the group holds the floor");
    v.field("intrusion", intrusion,
            "join_conversation: per entry into the group (the formation takes ARI in) while a "
            "member holds the floor");
    v.field("answer", answer,
            "join_conversation: per line ARI begins within conversation.answer_window after a "
            "member's question to it ended");
  }
};

/// When ARI has arrived: base_footprint this close to the goal pose, heading this close.
struct ArrivalRule {
  double position_tolerance_m{0.25};
  double heading_tolerance_rad{0.35};

  template <class V>
  void visit(V& v) {
    v.field("position_tolerance", position_tolerance_m, "m from the goal pose",
            core::Bounds{0.0, 2.0, true});
    v.field("heading_tolerance", heading_tolerance_rad, "rad from the goal's heading",
            core::Bounds{0.0, 3.1416, true});
  }
};

/// The join_conversation task's group and its judgement of ARI's answers.
struct ConversationTaskConfig {
  int group_size{3};
  double answer_window_s{3.0};

  template <class V>
  void visit(V& v) {
    v.field("group_size", group_size, "people in the conversation group ARI joins",
            core::between(2, 4));
    v.field("answer_window", answer_window_s,
            "s after the end of a member's question to ARI within which ARI's line counts as a "
            "prompt answer",
            core::between(0.5, 30.0));
  }
};

/// A navigation environment's task, observation and rewards (config/learning/<task>.yaml; every
/// key optional, unknown keys are errors).
struct NavTaskConfig {
  NavTask task{NavTask::kJoinGroup};
  std::string scenario;  // the scenario file of task scenario
  double time_limit_s{40.0};
  int walkers{0};
  bool perception_errors{true};
  bool terminate_on_collision{true};
  double goal_update_period_s{0.2};
  navigation::PolicyObservationConfig observation;
  RewardWeights rewards;
  ArrivalRule arrival;
  ConversationTaskConfig conversation;

  template <class V>
  void visit(V& v) {
    v.choice("task", task, "what the policy must do", kNavTaskNames);
    v.field("scenario", scenario,
            "task scenario: the scenario file whose scene, script and random draws are played, "
            "the policy driving ARI's goals");
    v.field("time_limit", time_limit_s, "s of sim time before the episode is truncated",
            core::between(1.0, 3600.0));
    v.field("walkers", walkers, "people walking between random places, besides the episode's own",
            core::between(0, 200));
    v.field("perception_errors", perception_errors,
            "perception's error models (misses, noise, id switches; config/perception.yaml)");
    v.field("terminate_on_collision", terminate_on_collision,
            "a contact with a person, wall or furniture ends the episode (not arrived)");
    v.field(
        "goal_update_period", goal_update_period_s,
        "s between placements of the goal (the goal finder, on the perceived and the true scene)",
        core::between(0.0, 10.0));
    v.section("observation", observation, "what the policy is shown");
    v.section("rewards", rewards, "weights of the reward's terms");
    v.section("arrival", arrival, "when the goal counts as reached");
    v.section("conversation", conversation, "join_conversation: the group and ARI's answers");
    v.rule("scenario", (task == NavTask::kScenario) == !scenario.empty(),
           "a file for task scenario and none for the other tasks",
           scenario.empty() ? "none" : scenario);
  }

  void validate() const;
  /// Reads a task file; throws core::ConfigError naming the file and field.
  static NavTaskConfig load_file(const std::string& path);
};

}  // namespace ari_social_sim::learning
