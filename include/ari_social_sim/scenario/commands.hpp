#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "ari_social_sim/core/pose2.hpp"
#include "ari_social_sim/scenario/agent_ref.hpp"
#include "ari_social_sim/world/group_navigation.hpp"
#include "ari_social_sim/world/human.hpp"
#include "ari_social_sim/world/posture.hpp"
#include "ari_social_sim/world/walking_group.hpp"

namespace ari_social_sim::scenario {

/// What a script can ask of the run. scenario_node implements it with the public services and
/// actions (/sim/..., /tts, move_base, /social_mpc/approach); the batch tool with the cores
/// in-process. Every method throws core::RequestError when the request is refused (unknown id,
/// spawn overlapping someone, no server), with the refusal's text.
class Commands {
 public:
  virtual ~Commands() = default;

  /// A human or ARI says `text` as speech act `act`; ARI speaks through its text-to-speech.
  virtual void say(const AgentRef& speaker, const std::string& act, const std::string& text) = 0;
  /// A human walks to a pose (leaving its group).
  virtual void set_human_goal(model::ObjectId human, const core::Pose2& goal) = 0;
  /// ARI navigates to a pose (move_base). Replaces any navigation goal in progress.
  virtual void navigate(const core::Pose2& goal) = 0;
  /// ARI approaches a person, or joins the group the person belongs to (/social_mpc/approach),
  /// named by the id perception reports it under. Replaces any navigation goal in progress.
  virtual void approach(const std::string& person_id, bool join_group) = 0;
  /// ARI's navigation fails at once with `reason`, as for a goal navigation rejects, for a goal
  /// that cannot even be named (a human perception has not matched with any person). Cancels any
  /// goal in progress; the failure lasts until the next goal or cancel.
  virtual void fail_navigation(const std::string& reason) = 0;
  /// ARI cancels its navigation goal.
  virtual void cancel_navigation() = 0;
  /// Spawns a human (profile and pose), then sets its goal and gaze targets if the spec has them.
  virtual void add_human(const world::HumanSpec& spec) = 0;
  virtual void remove_human(model::ObjectId human) = 0;
  virtual void create_group(const world::GroupSpec& spec) = 0;
  /// People walk together to a goal (/sim/create_walking_group).
  virtual void create_walking_group(const world::WalkingGroupSpec& spec) = 0;
  virtual void add_group_members(model::ObjectId group,
                                 const std::vector<model::ObjectId>& members) = 0;
  virtual void set_group_centre(model::ObjectId group, const Eigen::Vector2d& centre) = 0;
  virtual void set_group_arrangement(model::ObjectId group, model::Arrangement arrangement,
                                     std::optional<double> heading_rad) = 0;
  /// A human or ARI leaves its group (/sim/leave_group).
  virtual void leave_group(model::ObjectId agent) = 0;
  /// A human stands up or sits down in place (/sim/set_posture).
  virtual void set_posture(model::ObjectId human, world::Posture posture) = 0;
};

}  // namespace ari_social_sim::scenario
