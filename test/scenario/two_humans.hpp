#pragma once

#include "ari_social_sim/world/world_snapshot.hpp"

namespace ari_social_sim::scenario::test {

/// Humans 10 at (2, 2) and 11 at (3, 2), 1 m apart: the world the tests of who perception's
/// persons are see them in.
inline world::WorldSnapshot two_humans() {
  world::WorldSnapshot world;
  for (model::ObjectId id : {10u, 11u}) {
    world::HumanSnapshot human;
    human.id = id;
    human.pose.position = {id == 10 ? 2.0 : 3.0, 2.0};
    world.humans.push_back(human);
  }
  return world;
}

}  // namespace ari_social_sim::scenario::test
