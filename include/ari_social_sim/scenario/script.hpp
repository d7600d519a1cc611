#pragma once

#include <Eigen/Core>
#include <functional>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "ari_social_sim/core/pose2.hpp"
#include "ari_social_sim/scenario/agent_ref.hpp"
#include "ari_social_sim/scenario/random_group.hpp"
#include "ari_social_sim/world/group_navigation.hpp"
#include "ari_social_sim/world/human.hpp"
#include "ari_social_sim/world/posture.hpp"
#include "ari_social_sim/world/walking_group.hpp"

namespace ari_social_sim::scenario {

// ---- Conditions: what a transition waits for (docs/scenario.md section 4) ----

/// Centre-to-centre distance (m) from an agent to another agent or a fixed point, below or above
/// a threshold. ARI's position is base_footprint; a human's is the centre of its body.
struct DistanceCondition {
  AgentRef from;
  std::optional<AgentRef> to_agent;  // set: to an agent; unset: to `to_point`
  Eigen::Vector2d to_point{Eigen::Vector2d::Zero()};
  double distance_m{0.0};
  bool below{true};  // distance_below (true) or distance_above (false)
};

/// An utterance of `speaker` whose act matches `act` finished after the current state was entered
/// (D6.4's `previous_speech_act == act`). `act` is exact, or a prefix ending in `*`; `*` alone
/// matches any act.
struct SpeechFinishedCondition {
  AgentRef speaker;
  std::string act;
};

/// ARI: its last navigation goal (set_goal, approach, join_group) succeeded. A human: it has a goal
/// and stands within `tolerance_m` of it.
struct GoalReachedCondition {
  AgentRef who;
  double tolerance_m{0.3};
};

/// ARI's last navigation goal was aborted or rejected.
struct NavigationFailedCondition {};

/// At least `seconds` of sim time since the current state was entered.
struct TimeElapsedCondition {
  double seconds{0.0};
};

/// Perception reports a group (/humans/interactions/groups) that contains every listed agent.
struct PerceivedGroupCondition {
  std::vector<AgentRef> members;
};

/// The dialogue with the simulated humans (dialogue_node) has ended.
struct DialogueFinishedCondition {};

/// ARI's speech recognition gave, after the current state was entered, a final transcript taken
/// for a human line of the script whose act matches `act` (HeardLines; exact, or a prefix ending
/// in `*`). Unlike speech_finished, it waits for what ARI heard, not for what was said.
struct HeardCondition {
  std::string act;
};

/// ARI's speech recognition gave, after the current state was entered, a final transcript with
/// words that it could take for no human line of the script: what a dialogue system answers with
/// a request to repeat.
struct NotUnderstoodCondition {};

/// Nobody of `person`'s conversation group holds the floor (the world state's groups[].speaker;
/// backchannels take no floor): a pause to enter in. For a person in no group: the person is
/// silent.
struct FloorFreeCondition {
  model::ObjectId person{model::kNoObject};
};

/// Since the current state was entered, a member of a talking group ARI takes part in spoke to
/// ARI (the world state's groups[].addressee).
struct AddressedCondition {};

using Condition = std::variant<DistanceCondition, SpeechFinishedCondition, GoalReachedCondition,
                               NavigationFailedCondition, TimeElapsedCondition,
                               PerceivedGroupCondition, DialogueFinishedCondition, HeardCondition,
                               NotUnderstoodCondition, FloorFreeCondition, AddressedCondition>;

// ---- Actions: what entering a state or firing a transition does (section 5) ----

/// An agent says an act, word by word. ARI speaks through its text-to-speech (/tts).
struct SayAction {
  AgentRef speaker;
  std::string act;
  std::string text;
};

/// ARI: navigate to a pose (move_base). A human: walk to a pose (leaves its group).
struct SetGoalAction {
  AgentRef who;
  core::Pose2 goal;
};

/// ARI approaches a person (/social_mpc/approach, person target).
struct ApproachAction {
  model::ObjectId person{model::kNoObject};
};

/// ARI joins the group the person belongs to (/social_mpc/approach, group-of-person target).
struct JoinGroupAction {
  model::ObjectId person{model::kNoObject};
};

/// ARI cancels its navigation goal and stops.
struct CancelNavigationAction {};

struct AddHumanAction {
  world::HumanSpec human;
};

struct RemoveHumanAction {
  model::ObjectId human{model::kNoObject};
};

struct CreateGroupAction {
  world::GroupSpec group;
};

/// People walk together to a goal (/sim/create_walking_group, docs/world.md "Walking groups").
struct CreateWalkingGroupAction {
  world::WalkingGroupSpec group;
};

struct AddGroupMembersAction {
  model::ObjectId group{model::kNoObject};
  std::vector<model::ObjectId> members;
};

/// A human or ARI leaves its group (/sim/leave_group): a human steps out of the formation and the
/// others close the gap; ARI is no longer counted in it.
struct LeaveGroupAction {
  AgentRef who;
};

/// A group takes another arrangement (/sim/set_group_arrangement).
struct SetGroupArrangementAction {
  model::ObjectId group{model::kNoObject};
  model::Arrangement arrangement{model::Arrangement::kCircle};
  std::optional<double> heading_rad;
};

/// A human stands up or sits down in place (/sim/set_posture).
struct SetPostureAction {
  model::ObjectId human{model::kNoObject};
  world::Posture posture{world::Posture::kStanding};
};

struct SetGroupCentreAction {
  model::ObjectId group{model::kNoObject};
  Eigen::Vector2d centre{Eigen::Vector2d::Zero()};
};

/// ARI takes part in the dialogue with the simulated humans, answering what it hears with the
/// dialogue core's rule-based policy (dialogue::RulePolicy, opening with its greeting) until the
/// script leaves the state.
struct ConverseAction {};

/// Ends the run with an outcome (D6.4's `simulation.stop()`).
struct StopAction {
  bool success{true};
  std::string reason;
};

using Action =
    std::variant<SayAction, SetGoalAction, ApproachAction, JoinGroupAction, CancelNavigationAction,
                 AddHumanAction, RemoveHumanAction, CreateGroupAction, AddGroupMembersAction,
                 SetGroupCentreAction, LeaveGroupAction, SetGroupArrangementAction, ConverseAction,
                 StopAction, CreateWalkingGroupAction, SetPostureAction>;

// ---- The state machine ----

/// Fires when every condition holds (an empty list fires at once): runs its actions, then enters
/// `next` (which may be the same state, entered afresh). `next` is empty only when the actions
/// stop the run.
struct Transition {
  std::vector<Condition> when;
  std::vector<Action> actions;
  std::string next;
  std::string field;  // where it was written, e.g. `script.states[1].transitions[0]`
};

struct State {
  std::string name;
  std::vector<Action> on_enter;
  std::vector<Transition> transitions;  // checked in order; the first that holds fires
};

/// The run interfaces a script uses beyond the world's services, so that a runner waits for
/// exactly those before it starts.
struct ScriptInterfaces {
  bool text_to_speech{false};      // ARI says something (/tts)
  bool move_base{false};           // ARI goes to a pose
  bool approach{false};            // ARI approaches a person or joins a group
  bool perceived_groups{false};    // a condition on /humans/interactions/groups
  bool dialogue{false};            // ARI converses or a condition waits for the dialogue's end
  bool speech_recognition{false};  // a condition on what ARI heard (/humans/voices/*/speech)
};

/// Whether a speech act matches a script's pattern: exact, a prefix ending in `*`, or `*` alone.
bool act_matches(const std::string& pattern, const std::string& act);

/// The scripted part of a scenario (D6.4's Script, §3.7, as data).
struct Script {
  double time_limit_s{0.0};  // sim time after which the run ends as a failure
  std::vector<RandomGroup> random_groups;
  std::string start;
  std::vector<State> states;

  /// Index of the state with this name; throws std::out_of_range when there is none.
  size_t state_index(const std::string& name) const;
  ScriptInterfaces interfaces() const;
  /// Calls `visit` with every action of the script: each state's entry actions, then its
  /// transitions' actions, in the order written.
  void for_each_action(const std::function<void(const Action&)>& visit) const;
};

}  // namespace ari_social_sim::scenario
