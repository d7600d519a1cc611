#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "ari_social_sim/core/pose2.hpp"
#include "ari_social_sim/navigation/footprint_model.hpp"
#include "ari_social_sim/navigation/grid_field.hpp"
#include "ari_social_sim/navigation/navigation_config.hpp"
#include "ari_social_sim/navigation/perceived_scene.hpp"

namespace ari_social_sim::navigation {

/// Go to a base_footprint pose in the map frame.
struct PoseTarget {
  core::Pose2 pose;
};
/// Stand in front of a person, facing them (ROS4HRI person id).
struct PersonTarget {
  std::string person_id;
};
/// Join a group on its o-space circle, facing its centre (ROS4HRI group id).
struct GroupTarget {
  std::string group_id;
};
/// Join whichever group a person currently belongs to.
struct GroupOfPersonTarget {
  std::string person_id;
};
using NavigationTarget = std::variant<PoseTarget, PersonTarget, GroupTarget, GroupOfPersonTarget>;

/// A description of a target for messages ("person human3", "group g1", "pose (1.00, 2.00)").
std::string describe(const NavigationTarget& target);

/// Why `scene` cannot tell where the target is ("person human9 is not tracked", "person human2 is
/// in no group"), or "" when it can (always for a pose).
std::string unknown_target_reason(const NavigationTarget& target, const PerceivedScene& scene);

/// Where a target puts ARI, and what the planner should know about it.
struct Goal {
  core::Pose2 pose;                        // base_footprint goal, map frame
  std::optional<Eigen::Vector2d> look_at;  // person or o-space centre, for the head camera
  std::string group_id;                    // group joined (its o-space carries no cost)
  std::vector<std::string> target_people;  // person or members, whose spaces are scaled down
  double gap_angle{0.0};                   // rad, direction of the chosen gap from the centre
  double gap_width{0.0};                   // rad, width of that gap; 0 for other targets
  bool outside_circle{false};              // no gap had room: ARI stands just outside

  /// True for the person approached or a member of the group joined.
  bool is_target(const std::string& person_id) const {
    return std::find(target_people.begin(), target_people.end(), person_id) != target_people.end();
  }
};

/// Why a target has no goal now; a result rather than an exception, since in the control loop
/// it is a frequent, expected outcome (a person hidden for a moment, a group with no room yet).
struct GoalFailure {
  enum class Kind {
    kUnknownTarget,  ///< the target's id is not in the scene (unknown_target_reason)
    kUnreachable,    ///< no free place for ARI, or none ARI can reach
  };
  Kind kind{Kind::kUnreachable};
  std::string reason;
};

/// A goal for a target, or why there is none.
using GoalSearch = std::variant<Goal, GoalFailure>;

/// Turns a target into a goal pose (the project's own rules, docs/navigation.md):
/// - pose: the pose itself, if ARI's footprint fits there;
/// - person: base_footprint `approach_distance` in front of the person, within
///   `approach_max_angle` of their facing direction, facing them; the first free place in order
///   of angle off their facing direction, preferring places outside others' personal spaces;
/// - group: ARI's body centre on the o-space circle at the bisector of the widest gap whose arc
///   leaves ARI's width plus `gap_clearance` on each side, facing the centre (gaps within
///   `gap_width_tolerance` of each other count as equally wide, the one nearest ARI first);
///   otherwise the next gap; otherwise just outside the circle (`outside_offset`, stepping out
///   until the footprint is free) at the widest gap.
/// A goal found before for the same target is kept while still valid, so ARI does not hop between
/// gaps of a group whose members shuffle.
class GoalFinder {
 public:
  GoalFinder(const GoalFinderConfig& config, const FootprintModel& footprint,
             const PersonalSpaceParams& spaces);

  /// The goal, or a failure: kUnknownTarget if the target's id is not in `scene`, kUnreachable
  /// if no free place exists. `sdf` is the map's signed distance field, `robot` ARI's base pose.
  GoalSearch find(const NavigationTarget& target, const PerceivedScene& scene, const GridField& sdf,
                  const core::Pose2& robot,
                  const std::optional<Goal>& previous = std::nullopt) const;

  /// True when ARI's footprint at `base` keeps `margin_m` from walls, furniture and every body.
  bool is_free(const core::Pose2& base, const PerceivedScene& scene, const GridField& sdf,
               double margin_m) const;

 private:
  GoalSearch find_pose(const PoseTarget& target, const GridField& sdf) const;
  GoalSearch find_person(const PersonEstimate& person, const PerceivedScene& scene,
                         const GridField& sdf, const core::Pose2& robot,
                         const std::optional<Goal>& previous) const;
  GoalSearch find_group(const GroupEstimate& group, const PerceivedScene& scene,
                        const GridField& sdf, const core::Pose2& robot,
                        const std::optional<Goal>& previous) const;
  /// Free and outside every o-space but `group_id`'s and every personal space but `exempt`'s.
  bool is_polite(const core::Pose2& base, const PerceivedScene& scene, const std::string& group_id,
                 const std::vector<std::string>& exempt) const;
  /// Base pose putting ARI's body centre at `body_centre`, facing `heading`.
  core::Pose2 base_for_body_centre(const Eigen::Vector2d& body_centre, double heading) const;

  GoalFinderConfig config_;
  FootprintModel footprint_;
  PersonalSpaceParams spaces_;
};

}  // namespace ari_social_sim::navigation
