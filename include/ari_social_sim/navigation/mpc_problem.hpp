#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "ari_social_sim/core/pose2.hpp"
#include "ari_social_sim/navigation/geodesic_field.hpp"
#include "ari_social_sim/navigation/grid_field.hpp"
#include "ari_social_sim/navigation/perceived_scene.hpp"
#include "ari_social_sim/navigation/unicycle_model.hpp"

namespace ari_social_sim::navigation {

/// A person as one solve sees them: predicted at constant velocity, with the share of their
/// personal-space weight that applies (1, or less for the person ARI approaches or joins).
struct ProblemPerson {
  PersonEstimate estimate;
  double space_scale{1.0};
};

/// A group as one solve sees it; the group ARI joins has no o-space cost.
struct ProblemGroup {
  GroupEstimate estimate;
  bool is_target{false};
};

/// One MPC solve's inputs (all in the map frame). The fields are borrowed and must outlive the
/// solve.
struct MpcProblem {
  RobotState start;
  double start_linear_mps{0.0};   // measured base velocities, for the smoothness and
  double start_angular_rps{0.0};  // acceleration terms of the first step
  double start_pan_rps{0.0};
  const GridField* sdf{nullptr};           // signed distance to walls and furniture
  const GeodesicField* geodesic{nullptr};  // travel cost to goal.position
  core::Pose2 goal;                        // base_footprint goal pose
  bool at_goal_position{false};            // ARI stands at goal.position: now turn to its heading
  std::optional<Eigen::Vector2d> look_at;  // what the head camera should keep in view
  std::vector<ProblemPerson> people;
  std::vector<ProblemGroup> groups;
};

}  // namespace ari_social_sim::navigation
