#pragma once

// Small worlds built inline, shared by the world tests and bench/bench_world.cpp so that what is
// measured is what is tested.

#include <cmath>
#include <memory>
#include <string>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/rng.hpp"
#include "ari_social_sim/world/simulation.hpp"

namespace ari_social_sim::world::test {

/// A square room of `side_m` with 0.1 m walls along its edges, floor from (0, 0).
inline model::WorldDescription square_room(double side_m) {
  model::WorldDescription world;
  world.name = "room";
  world.origin = {-0.2, -0.2};
  world.size = {side_m + 0.4, side_m + 0.4};
  const double h = 0.5 * side_m;
  auto wall = [&](model::ObjectId id, double x, double y, double length, double theta) {
    model::StaticObject object;
    object.id = id;
    object.type = model::ShapeType::kWall;
    object.pose.position = {x, y};
    object.pose.theta = theta;
    object.size = {length, 0.1};
    world.objects.push_back(object);
  };
  wall(1001, h, 0.0, side_m + 0.1, 0.0);
  wall(1002, h, side_m, side_m + 0.1, 0.0);
  wall(1003, 0.0, h, side_m - 0.1, M_PI / 2);
  wall(1004, side_m, h, side_m - 0.1, M_PI / 2);
  return world;
}

/// Adds `count` humans at random free positions inside [margin, side - margin]^2.
inline std::vector<model::ObjectId> add_random_humans(Simulation& simulation, int count,
                                                      double side_m, double margin_m,
                                                      core::Rng& rng,
                                                      model::ObjectId first_id = 10) {
  std::vector<model::ObjectId> ids;
  model::ObjectId id = first_id;
  while (static_cast<int>(ids.size()) < count) {
    HumanSpec spec;
    spec.id = id;
    spec.pose.position = {rng.uniform(margin_m, side_m - margin_m),
                          rng.uniform(margin_m, side_m - margin_m)};
    spec.pose.theta = rng.uniform(-M_PI, M_PI);
    try {
      simulation.add_human(spec);
      ids.push_back(id++);
    } catch (const core::RequestError&) {
      // Overlapping draw: try another position.
    }
  }
  return ids;
}

}  // namespace ari_social_sim::world::test
