#pragma once

#include <Eigen/Core>
#include <vector>

#include "ari_social_sim/core/rng.hpp"
#include "ari_social_sim/world/group_navigation.hpp"
#include "ari_social_sim/world/human.hpp"

namespace ari_social_sim::scenario {

/// A group of randomised size and place added at the start (join_group): `size` members drawn
/// uniformly from [min_size, max_size], with ids first_human_id, first_human_id + 1, ...; the
/// o-space centre uniform in the box [centre_min, centre_max]; members evenly spread on the
/// automatic o-space circle, turned by a uniform random angle, facing the centre; each member's
/// age uniform in [18, 80] years and gender female or male with equal probability.
struct RandomGroup {
  model::ObjectId id{model::kNoObject};
  model::ObjectId first_human_id{model::kNoObject};
  unsigned min_size{2};
  unsigned max_size{2};
  Eigen::Vector2d centre_min{Eigen::Vector2d::Zero()};
  Eigen::Vector2d centre_max{Eigen::Vector2d::Zero()};
};

/// The humans and the group a RandomGroup stands for in one run.
struct GeneratedGroup {
  std::vector<world::HumanSpec> humans;
  world::GroupSpec group;
};

/// Draws one RandomGroup. The same generator state gives the same group.
GeneratedGroup generate_group(const RandomGroup& spec, core::Rng& rng);

}  // namespace ari_social_sim::scenario
