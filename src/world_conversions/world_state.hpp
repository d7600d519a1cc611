#pragma once

#include <geometry_msgs/Pose2D.h>
#include <nav_msgs/OccupancyGrid.h>

#include <optional>
#include <string>

#include "ari_social_sim/WorldState.h"
#include "ari_social_sim/core/pose2.hpp"
#include "ari_social_sim/model/occupancy_grid.hpp"
#include "ari_social_sim/world/world_snapshot.hpp"

namespace ari_social_sim::nodes {

/// geometry_msgs/Pose2D of a planar pose (the world services' poses and goals), and back.
geometry_msgs::Pose2D to_msg(const core::Pose2& pose);
core::Pose2 from_msg(const geometry_msgs::Pose2D& msg);

/// /sim/world_state from a snapshot; header stamped with the snapshot's sim time in `frame_id`.
WorldState to_msg(const world::WorldSnapshot& snapshot, const std::string& frame_id);
/// /map from the rasterised static geometry.
nav_msgs::OccupancyGrid to_msg(const model::OccupancyGrid& grid, const std::string& frame_id,
                               double stamp_s);

/// The snapshot a /sim/world_state message carries: the inverse of to_msg (the message holds a
/// speaker's previous act but no longer history).
world::WorldSnapshot from_msg(const WorldState& msg);
/// A human's posture from its state; POSTURE_UNSET (a publisher from before postures) and a
/// progress outside [0, 1] (input_problem refuses it) read as standing, settled.
world::PostureState posture_of(const HumanState& msg);
/// A /map message as a grid (an origin rotation, which the world never writes, is ignored).
model::OccupancyGrid from_msg(const nav_msgs::OccupancyGrid& msg);

/// What makes a received message unusable, as `field` and `what` ("humans[2].pose.x", "nan, not
/// a finite number"); nullopt when it is fine. A /sim/world_state needs finite numbers where the
/// consumers compute (stamp, poses, velocities, ages, head pan, gaze direction), known enum
/// values and reaction names (or none) and at most world::kMaxHumans humans; a /map a finite
/// resolution > 0, a finite origin, width x height cells (at most world::kMaxMapCells) and that
/// many values.
struct InputProblem {
  std::string field;
  std::string what;
};
std::optional<InputProblem> input_problem(const WorldState& msg);
std::optional<InputProblem> input_problem(const nav_msgs::OccupancyGrid& msg);

}  // namespace ari_social_sim::nodes
