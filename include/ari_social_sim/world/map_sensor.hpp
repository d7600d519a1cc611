#pragma once

#include "ari_social_sim/model/occupancy_grid.hpp"
#include "ari_social_sim/model/world_description.hpp"
#include "ari_social_sim/world/object.hpp"

namespace ari_social_sim::world {

/// Most cells an occupancy grid of a world may have: 4096 x 4096, which holds the largest world
/// (model::kMaxWorldSideM, 200 m) at the default 0.05 m resolution.
constexpr uint64_t kMaxMapCells = 4096ULL * 4096ULL;

/// Cells (width x height) of the occupancy grid covering the world's floor at this resolution.
/// Computed in double, so a huge count is reported rather than overflowing.
double map_cell_count(const model::WorldDescription& world, double resolution_m);
/// Throws core::ConfigError naming the resolution, the floor and the cell count when the grid would
/// have more than kMaxMapCells cells (or the resolution is not a finite number > 0), before
/// anything is allocated.
void check_map_size(const model::WorldDescription& world, double resolution_m);

/// Rasterises the static geometry (walls and furniture, never agents) into an occupancy grid
/// covering the world's floor: a cell is occupied when its square overlaps a shape (Box2D's exact
/// overlap test, so thin walls are never missed). Its cells are `requested_resolution_m` rounded
/// to float32, as /map carries them. Throws core::ConfigError from check_map_size.
model::OccupancyGrid rasterize_static_map(const model::WorldDescription& world,
                                          double requested_resolution_m);

/// D6.4 §3.5.1 MapSensor: ARI's occupancy map of the environment, replicating its mapping from the
/// static objects of the simulation. Static geometry never changes during a run, so the map is
/// built on the first sensor step and kept.
class MapSensor : public Component {
 public:
  explicit MapSensor(double resolution_m) : resolution_m_(resolution_m) {}

  ComponentPhase phase() const override { return ComponentPhase::kSensor; }
  void step(Object& owner, const StepContext& context) override;

  bool has_map() const { return has_map_; }
  const model::OccupancyGrid& map() const { return map_; }

 private:
  double resolution_m_;
  bool has_map_{false};
  model::OccupancyGrid map_;
};

}  // namespace ari_social_sim::world
