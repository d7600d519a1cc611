#pragma once

#include "ari_social_sim/world/object.hpp"
#include "ari_social_sim/world/occupancy_grid.hpp"
#include "ari_social_sim/world/world_description.hpp"

namespace ari_social_sim::world {

/// Rasterises the static geometry (walls and furniture, never agents) into an occupancy grid
/// covering the world's floor: a cell is occupied when its square overlaps a shape (Box2D's exact
/// overlap test, so thin walls are never missed).
OccupancyGrid rasterize_static_map(const WorldDescription& world, double resolution_m);

/// Seed 3.5.1 MapSensor: ARI's occupancy map of the environment, replicating its mapping from the
/// static objects of the simulation. Static geometry never changes during a run, so the map is
/// built on the first sensor step and kept.
class MapSensor : public Component {
 public:
  explicit MapSensor(double resolution_m) : resolution_m_(resolution_m) {}

  ComponentPhase phase() const override { return ComponentPhase::kSensor; }
  void step(Object& owner, const StepContext& context) override;

  bool has_map() const { return has_map_; }
  const OccupancyGrid& map() const { return map_; }

 private:
  double resolution_m_;
  bool has_map_{false};
  OccupancyGrid map_;
};

}  // namespace ari_social_sim::world
