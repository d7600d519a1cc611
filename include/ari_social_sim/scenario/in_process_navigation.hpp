#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ari_social_sim/model/occupancy_grid.hpp"
#include "ari_social_sim/navigation/navigation_config.hpp"
#include "ari_social_sim/navigation/navigator.hpp"
#include "ari_social_sim/navigation/scene_tracker.hpp"
#include "ari_social_sim/perception/group_perception.hpp"
#include "ari_social_sim/perception/perception_frame.hpp"
#include "ari_social_sim/scenario/observations.hpp"
#include "ari_social_sim/world/simulation.hpp"

namespace ari_social_sim::scenario {

/// A command social_mpc_node would publish: a twist on /mobile_base_controller/cmd_vel, with a
/// head pan target on /head_controller/command unless it is a stop.
struct SentCommand {
  double linear_mps{0.0};
  double angular_rps{0.0};
  std::optional<double> pan_rad;
};

/// social_mpc_node in-process (the batch tool's navigation): the same Navigator on the static
/// map, fed by a SceneTracker with what perception and group detection report (tracked persons at
/// their bodies' poses, groups), run at the navigator's rate on sim time, its commands applied to
/// ARI in the simulation. Goals follow the node's action semantics: a goal that cannot be started
/// fails with the reason, a new goal replaces the current one, a goal's end or a cancel stops the
/// base. Holds a reference to the simulation, which must outlive it.
class InProcessNavigation {
 public:
  InProcessNavigation(const navigation::NavigationConfig& config, const model::OccupancyGrid& map,
                      world::Simulation& simulation);

  /// What hri_perception_node published in a frame (/humans/persons/tracked, the bodies' tf
  /// frames) and the groups group_detection_node found in it (/humans/interactions/groups).
  void observe(const perception::PerceptionFrame& frame,
               const std::vector<perception::PerceivedGroup>& groups);
  /// A move_base goal, or an approach goal (join_group: TARGET_GROUP_OF_PERSON).
  void start(const navigation::NavigationTarget& target);
  void cancel();
  /// Cancels any goal and reports failure with `reason`, as for a rejected goal: the script's
  /// goal could not be named (Commands::fail_navigation).
  void fail(const std::string& reason);
  /// The control timer: one cycle when one is due at the simulation's time.
  void control();

  /// The state of the last goal, as its action client sees it.
  const NavigationStatus& status() const { return status_; }
  /// Commands sent since the previous call, which this call clears.
  std::vector<SentCommand> take_commands();

 private:
  void stop();

  navigation::NavigationConfig config_;
  world::Simulation& simulation_;
  navigation::SceneTracker tracker_;
  navigation::Navigator navigator_;
  double next_control_s_{0.0};
  NavigationStatus status_;
  std::vector<SentCommand> sent_;
};

}  // namespace ari_social_sim::scenario
