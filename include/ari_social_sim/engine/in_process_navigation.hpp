#pragma once

#include <memory>
#include <string>
#include <vector>

#include "ari_social_sim/model/occupancy_grid.hpp"
#include "ari_social_sim/model/tracked_person.hpp"
#include "ari_social_sim/navigation/navigation_config.hpp"
#include "ari_social_sim/navigation/navigation_session.hpp"
#include "ari_social_sim/perception/group_perception.hpp"
#include "ari_social_sim/perception/perception_frame.hpp"
#include "ari_social_sim/scenario/observations.hpp"
#include "ari_social_sim/world/simulation.hpp"

namespace ari_social_sim::engine {

/// A goal's state as the script sees it through its action client (scenario_node's status_of):
/// waiting or pursued is active, rejected or aborted a failure with the reason, cancelled no goal.
scenario::NavigationStatus as_seen_by_the_script(const navigation::GoalStatus& goal);

/// social_mpc_node in-process (the batch tool's navigation): the same NavigationSession (goal
/// life cycle, control timer, Navigator) on the static map, told what perception last published
/// and the groups group detection reported, run at every world step on sim time, its commands
/// applied to ARI in the simulation as world_node applies cmd_vel and head commands. The script's
/// view of its last goal is scenario_node's view of its action client. Holds a reference to the
/// simulation, which must outlive it.
class InProcessNavigation {
 public:
  /// `policy`, when given, drives the goals in SocialMPC's place (NavigationSession).
  InProcessNavigation(const navigation::NavigationConfig& config, const model::OccupancyGrid& map,
                      world::Simulation& simulation,
                      std::shared_ptr<navigation::Policy> policy = nullptr);

  /// What hri_perception_node published in its last frame (/humans/persons/tracked, the persons'
  /// body_id and the bodies' tf frames); the session reads it when it next looks at perception.
  void perceive(const perception::PerceptionFrame& frame);
  /// The groups group_detection_node published at `time_s` (/humans/interactions/groups).
  void receive_groups(const std::vector<perception::PerceivedGroup>& groups, double time_s);
  /// A move_base goal, or an approach goal (join_group: TARGET_GROUP_OF_PERSON).
  void start(const navigation::NavigationTarget& target);
  /// Cancels the last goal; the script then sees no goal, as scenario_node does.
  void cancel();
  /// Cancels the last goal and reports failure with `reason`: the script's goal could not be
  /// named (Commands::fail_navigation).
  void fail(const std::string& reason);
  /// social_mpc_node's timer: the session runs a cycle when one is due at the simulation's time.
  void control();

  /// The state of the last goal, as its action client sees it.
  const scenario::NavigationStatus& status() const { return status_; }
  /// Commands sent since the previous call, which this call clears.
  std::vector<navigation::BaseCommand> take_commands();

 private:
  navigation::SessionInputs inputs() const;
  void apply(const navigation::SessionOutput& out);

  world::Simulation& simulation_;
  navigation::NavigationSession session_;
  model::TrackedPersons perceived_;
  navigation::GoalId goal_{0};  // the last goal; 0 after a cancel
  scenario::NavigationStatus status_;
  std::vector<navigation::BaseCommand> sent_;
};

}  // namespace ari_social_sim::engine
