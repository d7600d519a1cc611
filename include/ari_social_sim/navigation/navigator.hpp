#pragma once

#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "ari_social_sim/core/pose2.hpp"
#include "ari_social_sim/model/occupancy_grid.hpp"
#include "ari_social_sim/navigation/geodesic_field.hpp"
#include "ari_social_sim/navigation/goal_controller.hpp"
#include "ari_social_sim/navigation/goal_finder.hpp"
#include "ari_social_sim/navigation/navigation_config.hpp"
#include "ari_social_sim/navigation/social_mpc.hpp"

namespace ari_social_sim::navigation {

/// The control loop shared by social_mpc_node and the benchmark: resolves the target into a goal
/// pose each cycle (GoalFinder), keeps the geodesic field to it up to date, runs the MPC, detects
/// arrival, and aborts with a reason when the goal is unreachable, the target is lost beyond the
/// timeout, or ARI makes no progress. Holds the static map's signed distance field.
class Navigator : public GoalController {
 public:
  /// Throws core::ConfigError for an invalid config (NavigationConfig::validate).
  Navigator(const NavigationConfig& config, const model::OccupancyGrid& map);
  Navigator(const Navigator&) = delete;
  Navigator& operator=(const Navigator&) = delete;

  /// Starts a new goal, replacing any other. Throws core::RequestError for a malformed target
  /// (check_target: a non-finite pose, an empty id), UnknownTarget when the target's id is not in
  /// `scene`, GoalUnreachable when the goal pose cannot be placed or reached from `robot`.
  void start(const NavigationTarget& target, const PerceivedScene& scene,
             const RobotObservation& robot, double time_s) override;
  /// Stops pursuing the goal (state back to idle).
  void cancel() override;
  /// One control cycle at sim time `time_s`. Never throws: a target lost or out of reach is an
  /// outcome of the cycle (kept pursuing for a while, or aborted with the reason).
  NavigatorStep update(double time_s, const RobotObservation& robot,
                       const PerceivedScene& scene) override;

  NavigationState state() const { return state_; }
  const GridField& sdf() const override { return sdf_; }
  const FootprintModel& footprint() const { return footprint_; }
  const NavigationConfig& config() const { return config_; }
  /// The current goal and its geodesic field (null before the first goal).
  const std::optional<Goal>& goal() const override { return goal_; }
  const GeodesicField* geodesic() const { return geodesic_.get(); }
  /// The last plan and the problem it solved.
  const MpcSolution& plan() const { return plan_; }
  const MpcProblem& problem() const { return problem_; }
  const std::optional<NavigationTarget>& target() const { return target_; }

 private:
  /// The areas the geodesic field routes around: standing people, groups not joined.
  std::vector<CostDisc> cost_discs(const PerceivedScene& scene, const Goal& goal) const;
  bool discs_changed(const std::vector<CostDisc>& discs) const;
  /// A geodesic field to a goal, or why ARI cannot reach the goal.
  using FieldSearch = std::variant<std::unique_ptr<GeodesicField>, GoalFailure>;
  /// The geodesic field to `goal`, or a kUnreachable failure when the goal or ARI cannot reach it.
  FieldSearch field_to(const Goal& goal, const core::Pose2& robot,
                       const std::vector<CostDisc>& discs) const;
  /// Sets goal_, rebuilding the geodesic field when the goal or the people moved; a goal within
  /// goal_update_distance and goal_update_angle of goal_ keeps goal_'s pose. A failure
  /// (kUnreachable) leaves the goal and its field as they were.
  std::optional<GoalFailure> adopt_goal(const Goal& goal, const core::Pose2& robot,
                                        const PerceivedScene& scene);
  /// Resolves the target into a goal at `time_s` and adopts it, unless it jumped away less than
  /// goal_switch_time ago; a failure (target unknown or unreachable) keeps the last goal.
  std::optional<GoalFailure> follow_target(double time_s, const core::Pose2& robot,
                                           const PerceivedScene& scene);
  NavigatorStep finish(NavigationState state, const std::string& reason);
  /// A group target whose id perception no longer reports continues as the group that shares
  /// the most of its last members (at least two): group detection gives a group a new id when
  /// its membership changes for a moment (a member hidden from ARI), and the group is still there.
  void follow_relabelled_group(const PerceivedScene& scene);
  /// A person target (or the person whose group is joined) whose id perception no longer tracks
  /// continues as the tracked person nearest to where the target was last seen, within
  /// kReidentifiedWithinM: a person manager gives a person a new id when it merges or restarts
  /// their tracks (hri_person_manager's anonymous persons), and the person is still there.
  void follow_relabelled_person(const PerceivedScene& scene);
  static constexpr double kReidentifiedWithinM = 0.5;
  /// When nobody is within kReidentifiedWithinM of a lost target whose group ARI joins: the
  /// member nearest to where the target was last seen, of a group that kept every other member
  /// of the target's last group and is no smaller, among the ids that group did not have. The
  /// person manager ended the target's track while their face's track stays grouped in their
  /// place, farther than a relabelling moves a track; nullptr when no group qualifies.
  const PersonEstimate* newcomer_in_target_group(const PerceivedScene& scene) const;
  /// True when base_footprint at `robot` is within goal_tolerance of the goal, and, for a join,
  /// at most join_shortfall_tolerance short of it along the goal's heading (toward the centre).
  bool at_goal_position(const core::Pose2& robot) const;
  /// Weight factor of personal spaces, 1 until ARI has been stalled for the patience time.
  double patience(double time_s) const;
  /// True when ARI's footprint at `robot` is inside the personal space of someone other than the
  /// person approached or the members joined.
  bool inside_bystander_space(const core::Pose2& robot, const PerceivedScene& scene) const;
  void build_problem(double time_s, const RobotObservation& robot, const PerceivedScene& scene);

  NavigationConfig config_;
  FootprintModel footprint_;
  GridField sdf_;
  GoalFinder goal_finder_;
  SocialMpc mpc_;
  NavigationState state_{NavigationState::kIdle};
  std::optional<NavigationTarget> target_;
  std::optional<Goal> goal_;
  std::unique_ptr<GeodesicField> geodesic_;
  std::vector<CostDisc> field_discs_;  // the discs geodesic_ was built with
  double target_seen_s_{0.0};
  // Of a group target, or of the group the target person was last seen in.
  std::vector<std::string> target_members_;
  std::optional<Eigen::Vector2d> target_person_seen_at_;  // of a person's target, when last seen
  bool aligning_{false};                // at the goal position, turning to the goal heading
  std::optional<double> jump_since_s_;  // since when the goal finder wants a distant new goal
  double best_distance_m_{0.0};
  double best_distance_time_s_{0.0};
  // Progress that restarts patience; once personal spaces have given way it only counts with
  // ARI clear of them, so that the way claimed through someone's space is kept until through.
  double patience_clock_s_{0.0};
  std::vector<Eigen::Vector2d> outline_;  // ARI's footprint outline, for inside_bystander_space
  MpcProblem problem_;
  MpcSolution plan_;
};

}  // namespace ari_social_sim::navigation
