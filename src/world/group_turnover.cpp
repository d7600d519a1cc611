#include "ari_social_sim/world/group_turnover.hpp"

#include <cmath>
#include <utility>
#include <vector>

#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/world/group_navigation.hpp"
#include "ari_social_sim/world/human.hpp"
#include "ari_social_sim/world/simulation.hpp"

namespace ari_social_sim::world {
namespace {

// Directions tried for a leaver's goal, from straight out of the ring round to either side: a
// wall or a table behind the member turns them aside rather than keeping them in.
constexpr int kLeaveDirections = 8;

// Chance of at least one event of a Poisson process of `rate_per_min` within `dt_s`.
double chance_within(double rate_per_min, double dt_s) {
  return 1.0 - std::exp(-rate_per_min * dt_s / 60.0);
}

}  // namespace

GroupTurnover::GroupTurnover(GroupTurnoverSpec spec, core::Rng rng)
    : spec_(spec), rng_(std::move(rng)) {}

void GroupTurnover::step(Simulation& simulation, const GroupNavigation& group, double dt_s) {
  const int members = static_cast<int>(group.members().size());
  // Both draws every step, whatever the group's size, so one process never shifts the other's.
  const bool departs = rng_.bernoulli(chance_within(spec_.leave_rate_per_min * members, dt_s));
  const bool arrives = rng_.bernoulli(chance_within(spec_.join_rate_per_min, dt_s));
  if (departs && members > spec_.min_members) {
    leave(simulation, group);
  }
  if (arrives && static_cast<int>(group.members().size()) < spec_.max_members) {
    arrive(simulation, group);
  }
}

// A member who is not speaking leaves (one who is finishes first: the next draw may take them),
// steps out of the ring and walks to the first free place leave_distance from the centre.
void GroupTurnover::leave(Simulation& simulation, const GroupNavigation& group) {
  std::vector<model::ObjectId> quiet;
  for (model::ObjectId id : group.members()) {
    const Human* human = simulation.find_human(id);
    if (human != nullptr && !human->speech().is_speaking()) {
      quiet.push_back(id);
    }
  }
  if (quiet.empty()) {
    return;
  }
  const model::ObjectId leaver = quiet[rng_.uniform_index(quiet.size())];
  const Eigen::Vector2d centre = group.centre();
  const Human& human = *simulation.find_human(leaver);
  const Eigen::Vector2d out = human.pose().position - centre;
  const double bearing = out.squaredNorm() > 1e-12 ? std::atan2(out.y(), out.x()) : 0.0;
  const double radius = human.spec().motion.body_radius_m;
  left_.insert(leaver);
  for (int k = 0; k < kLeaveDirections; ++k) {
    // 0, +1, -1, +2, -2, ... eighths of a turn off straight out.
    const int side = (k + 1) / 2 * (k % 2 == 1 ? 1 : -1);
    const double theta = core::wrap_angle(bearing + side * 2.0 * core::kPi / kLeaveDirections);
    const Eigen::Vector2d goal =
        centre + spec_.leave_distance_m * Eigen::Vector2d(std::cos(theta), std::sin(theta));
    if (simulation.world().contains(goal) && simulation.static_clearance_m(goal, radius) > 0.0) {
      simulation.set_human_goal(leaver, {goal, theta});
      return;
    }
  }
  simulation.leave_group(leaver);  // nowhere free to go: one step out of the ring
}

// The nearest person in no group (not walking with one) within join_radius of the centre joins,
// unless they left this group before.
void GroupTurnover::arrive(Simulation& simulation, const GroupNavigation& group) {
  model::ObjectId nearest = model::kNoObject;
  double nearest_m = spec_.join_radius_m;
  for (const Human* human : simulation.humans()) {
    if (human->group_id() != model::kNoObject || left_.count(human->id()) > 0) {
      continue;
    }
    const double distance_m = (human->pose().position - group.centre()).norm();
    if (distance_m < nearest_m) {
      nearest_m = distance_m;
      nearest = human->id();
    }
  }
  if (nearest != model::kNoObject) {
    simulation.join_group(group.id(), nearest);
  }
}

}  // namespace ari_social_sim::world
