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

/// D6.4's group model alone: no stances, spacings of their own, attention or shifts (issue 31's
/// member manners off), so that a test can check the equations' geometry exactly.
inline void without_manners(GroupSpec& group) {
  group.facing_spread_deg = 0.0;
  group.spacing_spread = 0.0;
  group.row_spacing_spread.reset();
  group.row_facing_spread_deg.reset();
  group.attention = 0.0;
  group.shift_m = 0.0;
  group.shift_turn_deg = 0.0;
}

/// A small world every kind of request can act on: square_room(6) (floor [-0.2, 6.2] on both
/// axes), humans 10 at (2, 2) and 11 at (4, 2) in group 1 around (3, 2), 12 standing at (3, 4),
/// ARI (id 1) at (1, 5).
inline std::unique_ptr<Simulation> request_world() {
  auto simulation = std::make_unique<Simulation>(square_room(6.0), SimulationConfig{});
  auto add_human = [&](model::ObjectId id, double x, double y) {
    HumanSpec spec;
    spec.id = id;
    spec.pose.position = {x, y};
    simulation->add_human(spec);
  };
  add_human(10, 2.0, 2.0);
  add_human(11, 4.0, 2.0);
  add_human(12, 3.0, 4.0);
  AriSpec ari;
  ari.pose = {{1.0, 5.0}, 0.0};
  simulation->add_ari(ari);
  GroupSpec group;
  group.id = 1;
  group.members = {10, 11};
  group.centre = {3.0, 2.0};
  without_manners(group);  // still, so that requests' effects are measured alone
  simulation->add_group(group);
  return simulation;
}

}  // namespace ari_social_sim::world::test
