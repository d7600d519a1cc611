#pragma once

#include <set>

#include "ari_social_sim/core/rng.hpp"
#include "ari_social_sim/model/object_id.hpp"
#include "ari_social_sim/world/group_turnover_spec.hpp"

namespace ari_social_sim::world {

class GroupNavigation;
class Simulation;

/// A conversation group's comings and goings (docs/world.md section 4.7): departures and arrivals
/// are Poisson processes of the spec's rates, drawn from the group's own stream. A member who
/// leaves walks off through the world's leave_group and a goal leave_distance from the centre;
/// a passer-by who joins does so through join_group, as a scenario's request would.
class GroupTurnover {
 public:
  GroupTurnover(GroupTurnoverSpec spec, core::Rng rng);

  /// Draws this step's departure and arrival (at most one of each) and makes them happen.
  void step(Simulation& simulation, const GroupNavigation& group, double dt_s);

  const GroupTurnoverSpec& spec() const { return spec_; }

 private:
  void leave(Simulation& simulation, const GroupNavigation& group);
  void arrive(Simulation& simulation, const GroupNavigation& group);

  GroupTurnoverSpec spec_;
  core::Rng rng_;
  /// Who left this group: they do not walk straight back in as passers-by.
  std::set<model::ObjectId> left_;
};

}  // namespace ari_social_sim::world
