#pragma once

// Small scenes built inline, shared by the navigation tests and bench/bench_navigation.cpp.

#include <memory>
#include <string>

#include "ari_social_sim/navigation/geodesic_field.hpp"
#include "ari_social_sim/navigation/mpc_problem.hpp"
#include "ari_social_sim/navigation/signed_distance_field.hpp"
#include "ari_social_sim/world/map_sensor.hpp"
#include "scene_builders.hpp"

namespace ari_social_sim::navigation::test {

/// The occupancy grid of world::test::square_room(side_m) at 0.05 m.
inline model::OccupancyGrid room_map(double side_m) {
  return world::rasterize_static_map(world::test::square_room(side_m), 0.05);
}

inline PersonEstimate person(const std::string& id, double x, double y, double heading,
                             Eigen::Vector2d velocity = Eigen::Vector2d::Zero()) {
  PersonEstimate p;
  p.id = id;
  p.position = {x, y};
  p.heading = heading;
  p.velocity = velocity;
  return p;
}

/// A room, its fields and a problem of going from `start` to `goal` in it, with nobody around.
struct RoomProblem {
  model::OccupancyGrid map;
  GridField sdf;
  std::unique_ptr<GeodesicField> geodesic;
  MpcProblem problem;

  RoomProblem(double side_m, const core::Pose2& start, const core::Pose2& goal)
      : map(room_map(side_m)), sdf(signed_distance_field(map)) {
    geodesic = std::make_unique<GeodesicField>(sdf, goal.position, GeodesicParams{});
    problem.start.position = start.position;
    problem.start.theta = start.theta;
    problem.sdf = &sdf;
    problem.geodesic = geodesic.get();
    problem.goal = goal;
  }
};

inline core::Pose2 pose(double x, double y, double theta) {
  core::Pose2 p;
  p.position = {x, y};
  p.theta = theta;
  return p;
}

}  // namespace ari_social_sim::navigation::test
