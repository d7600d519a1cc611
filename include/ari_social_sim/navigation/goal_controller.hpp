#pragma once

#include <optional>
#include <string>

#include "ari_social_sim/core/pose2.hpp"
#include "ari_social_sim/navigation/goal_finder.hpp"
#include "ari_social_sim/navigation/grid_field.hpp"
#include "ari_social_sim/navigation/perceived_scene.hpp"

namespace ari_social_sim::navigation {

/// ARI as the control loop measures it.
struct RobotObservation {
  core::Pose2 pose;        // base_footprint in the map frame
  double linear_mps{0.0};  // base velocities (odometry)
  double angular_rps{0.0};
  double pan_rad{0.0};  // head_1_joint
  double pan_rps{0.0};
};

/// What to send to ARI now.
struct NavigationCommand {
  double linear_mps{0.0};
  double angular_rps{0.0};
  double pan_rad{0.0};  // head_1_joint position target
};

enum class NavigationState { kIdle, kActive, kSucceeded, kAborted };

/// The outcome of one control cycle.
struct NavigatorStep {
  NavigationState state{NavigationState::kIdle};
  std::string phase;   // "approaching", "aligning", "waiting for the target", ...
  std::string reason;  // why the goal was aborted
  NavigationCommand command;
  double distance_to_goal_m{0.0};  // along the geodesic field
  bool replanned{false};           // this cycle ran the MPC
};

/// What drives ARI to a goal, cycle by cycle: SocialMPC (Navigator) or a learned policy
/// (PolicyController). NavigationSession runs either the same way.
class GoalController {
 public:
  virtual ~GoalController() = default;

  /// Starts a new goal, replacing any other. Throws core::RequestError for a malformed target
  /// (check_target), UnknownTarget when the target's id is not in `scene`, GoalUnreachable when
  /// the goal pose cannot be placed or reached from `robot`.
  virtual void start(const NavigationTarget& target, const PerceivedScene& scene,
                     const RobotObservation& robot, double time_s) = 0;
  /// Stops pursuing the goal (state back to idle).
  virtual void cancel() = 0;
  /// One control cycle at sim time `time_s`. Never throws: a target lost or out of reach is an
  /// outcome of the cycle.
  virtual NavigatorStep update(double time_s, const RobotObservation& robot,
                               const PerceivedScene& scene) = 0;

  /// The current goal (null before the first).
  virtual const std::optional<Goal>& goal() const = 0;
  /// The static map's signed distance field it plans on.
  virtual const GridField& sdf() const = 0;
};

}  // namespace ari_social_sim::navigation
