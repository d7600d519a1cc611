#include "ari_social_sim/scenario/random_group.hpp"

#include <cmath>

#include "ari_social_sim/core/angles.hpp"

namespace ari_social_sim::scenario {

GeneratedGroup generate_group(const RandomGroup& spec, core::Rng& rng) {
  GeneratedGroup generated;
  world::GroupSpec& group = generated.group;
  group.id = spec.id;
  const unsigned size =
      spec.min_size + static_cast<unsigned>(rng.uniform_index(spec.max_size - spec.min_size + 1));
  group.centre = {rng.uniform(spec.centre_min.x(), spec.centre_max.x()),
                  rng.uniform(spec.centre_min.y(), spec.centre_max.y())};
  const double radius_m = world::GroupNavigation::ospace_radius_for(
      size, world::GroupNavigation::member_spacing_for(group, size), group.min_ospace_radius_m);
  const double turn_rad = rng.uniform(-core::kPi, core::kPi);
  for (unsigned k = 0; k < size; ++k) {
    world::HumanSpec human;
    human.id = spec.first_human_id + k;
    const double bearing_rad = turn_rad + 2.0 * core::kPi * k / size;
    human.pose.position =
        group.centre + radius_m * Eigen::Vector2d(std::cos(bearing_rad), std::sin(bearing_rad));
    human.pose.theta = core::wrap_angle(bearing_rad + core::kPi);  // facing the centre
    // Whole years, as scene files give ages: /sim/spawn_human and /sim/world_state carry them as
    // float32, which holds whole years exactly, so live and batch runs perceive the same ages.
    human.age_years = std::floor(rng.uniform(18.0, 81.0));
    human.gender = rng.bernoulli(0.5) ? model::Gender::kFemale : model::Gender::kMale;
    group.members.push_back(human.id);
    generated.humans.push_back(human);
  }
  return generated;
}

}  // namespace ari_social_sim::scenario
