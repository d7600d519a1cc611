#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ari_social_sim/model/occupancy_grid.hpp"
#include "ari_social_sim/model/tracked_person.hpp"
#include "ari_social_sim/navigation/mlp_policy.hpp"
#include "ari_social_sim/navigation/navigation_config.hpp"
#include "ari_social_sim/navigation/navigator.hpp"
#include "ari_social_sim/navigation/perception_report.hpp"
#include "ari_social_sim/navigation/scene_tracker.hpp"

namespace ari_social_sim::navigation {

/// Where a goal is in its life, in the terms of its action client (actionlib's goal states).
enum class GoalState {
  kPending,    ///< waiting for its target to be perceived (kTargetWait_s)
  kActive,     ///< pursued
  kSucceeded,  ///< reached
  kRejected,   ///< never pursued: its target was not perceived in time, or a newer goal came first
  kAborted,  ///< it could not be started (no map, no pose of ARI, no place or path) or was given up
  kCanceled,  ///< cancelled by its client, or preempted by a newer goal
};

struct GoalStatus {
  GoalState state{GoalState::kPending};
  std::string reason;  ///< why it ended, when it did not succeed
};

/// A session's name for a goal, unique within the session; 0 names none.
using GoalId = uint64_t;

/// A goal whose state changed, for the caller to tell the goal's client.
struct GoalChange {
  GoalId goal{0};
  GoalStatus status;
};

/// What to send to ARI: a twist (/mobile_base_controller/cmd_vel) and, unless it stops the base,
/// a head pan target (/head_controller/command).
struct BaseCommand {
  double linear_mps{0.0};
  double angular_rps{0.0};
  std::optional<double> pan_rad;
};

/// What the session is told at a call: the sim time, ARI as measured (nothing while it cannot be
/// placed in the map), and the persons perception tracks now with where their bodies stand (tf
/// live, the last perception frame in process).
struct SessionInputs {
  double now_s{0.0};
  std::optional<RobotObservation> robot;
  model::TrackedPersons perception;
};

/// What a call produced, in order: goals whose state changed, commands to send, and the
/// control cycle's outcome when one ran with a goal being pursued.
struct SessionOutput {
  std::vector<GoalChange> goals;
  std::vector<BaseCommand> commands;
  std::optional<NavigatorStep> step;
};

/// ARI's social navigation as a service, the one way social_mpc_node and the batch tool's
/// navigation both run it: the goal life cycle of the move_base and approach actions, and the
/// control timer. Goals: a request replaces any goal still waiting; one whose target perception
/// does not report yet waits for it for kTargetWait_s; a goal that cannot be started is aborted
/// with the reason and the goal pursued before goes on; one that starts preempts the goal pursued
/// before; cancel ends a goal; whenever a pursued goal ends, the base is stopped (a zero twist).
/// Control: kLooksPerCycle times per control period (1/control_rate_hz() of sim time) it looks at
/// perception (tracked persons at their bodies, the groups received since the last look:
/// navigation::observe), and once per period it runs a cycle: it starts a waiting goal whose
/// target is now known and runs the Navigator on the pursued goal. Each happens at the first
/// control() call in its period, counted from sim time 0, so that they fall on the same sim times
/// whoever calls and however often. Perception is also looked at when a goal is requested. The
/// times, poses and headings it is told are rounded to 1e-6 (s, m, rad; headings into [-pi, pi)),
/// so that the rounding of their way to it (tf's quaternions) cannot change a plan. ARI's pose
/// and the bodies' placements are used only when finite and within model::kMaxMapCoordinateM of
/// the map origin (a rogue transform is no pose). When sim time goes back (a world reset, /clock
/// restarted) everything kept by time starts afresh: the tracker forgets everyone, the goal
/// pursued is aborted with the reason, a waiting goal waits its full kTargetWait_s again.
class NavigationSession {
 public:
  /// How long (s of sim time) a goal naming someone not perceived yet waits before it is
  /// rejected: a client may have learnt the id a moment before navigation perceives the person
  /// (their body's first frames).
  static constexpr double kTargetWait_s = 2.0;
  /// How often per control cycle perception is looked at: the tracker then hears perception at
  /// 20 Hz, as often as group detection reports and perception perceives at the world's default
  /// 0.05 s step (looked at 10 Hz, joins of join_group took 0.9 s longer at the median of 500
  /// seeds).
  static constexpr int kLooksPerCycle = 2;

  /// Drives goals with `policy` when given, else with the learned policy of
  /// `controller.policy_file` when it names one (docs/learning.md), else with SocialMPC. Throws
  /// core::ConfigError naming the policy file when it cannot be read.
  explicit NavigationSession(const NavigationConfig& config,
                             std::shared_ptr<Policy> policy = nullptr);
  NavigationSession(const NavigationSession&) = delete;
  NavigationSession& operator=(const NavigationSession&) = delete;

  /// The static map to plan on (/map); before one, goals are aborted. A goal being pursued is
  /// aborted: its way was planned on the other map.
  SessionOutput set_map(const model::OccupancyGrid& map);
  /// A group perception reported (/humans/interactions/groups); kept until perception is looked
  /// at next, so that every report reaches the scene, however many arrive per cycle.
  void receive_group(ReportedGroup group);
  /// A new goal; its id is newest_goal() from now on. Throws nothing: a goal that cannot be
  /// pursued ends in the output with the reason.
  SessionOutput request(const NavigationTarget& target, const SessionInputs& inputs);
  /// Ends `goal` (waiting or pursued) as cancelled by its client; other ids are ignored.
  SessionOutput cancel(GoalId goal);
  /// The control timer: call it at least kLooksPerCycle times per control period (every world
  /// step in process); does nothing unless a look at perception or a cycle is due at
  /// inputs.now_s.
  SessionOutput control(const SessionInputs& inputs);

  GoalId newest_goal() const { return next_goal_ - 1; }
  /// The goal being pursued, 0 when none.
  GoalId pursued_goal() const { return pursued_.value_or(0); }
  /// What drives the goals (the goal's placement, the map); null before the map.
  const GoalController* controller() const { return controller_.get(); }
  /// SocialMPC's navigator, for what the caller shows of it (plan, markers); null before the map
  /// and when a learned policy drives.
  const Navigator* navigator() const { return navigator_; }
  /// Control cycles per second of sim time: the controller's rate, or the policy's.
  double control_rate_hz() const { return control_rate_hz_; }

 private:
  struct WaitingGoal {
    GoalId id{0};
    NavigationTarget target;
    double until_s{0.0};
  };

  void look_at_perception(const SessionInputs& inputs);
  /// Starts the waiting goal once its target is known, rejects it once it has waited too long.
  void try_waiting_goal(const SessionInputs& inputs, SessionOutput& out);
  void start(GoalId id, const NavigationTarget& target, const SessionInputs& inputs,
             SessionOutput& out);
  /// Restarts what is kept by time when `now_s` is before the last time told (see the class).
  void follow_clock(double now_s, SessionOutput& out);
  /// Ends the pursued goal with `status` and stops the base.
  void end_pursued(const GoalStatus& status, SessionOutput& out);

  NavigationConfig config_;
  SceneTracker tracker_;
  std::shared_ptr<Policy> policy_;
  double control_rate_hz_{0.0};
  std::unique_ptr<GoalController> controller_;
  const Navigator* navigator_{nullptr};         // controller_, when SocialMPC drives
  std::vector<ReportedGroup> received_groups_;  // since perception was last looked at
  std::optional<WaitingGoal> waiting_;
  std::optional<GoalId> pursued_;
  GoalId next_goal_{1};
  std::optional<int64_t> last_cycle_;  // the control period of the last cycle
  std::optional<int64_t> last_look_;   // the look period of the last look at perception
  std::optional<double> last_now_s_;   // the last time told, to see it go back
};

}  // namespace ari_social_sim::navigation
