#include "ari_social_sim/world/map_sensor.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/number_text.hpp"
#include "ari_social_sim/world/box2d_shapes.hpp"
#include "ari_social_sim/world/simulation.hpp"

namespace ari_social_sim::world {

namespace {

int cells_along(double extent_m, double resolution_m) {
  return static_cast<int>(std::ceil(extent_m / resolution_m - 1e-9));
}

}  // namespace

double map_cell_count(const model::WorldDescription& world, double resolution_m) {
  return std::ceil(world.size.x() / resolution_m - 1e-9) *
         std::ceil(world.size.y() / resolution_m - 1e-9);
}

void check_map_size(const model::WorldDescription& world, double resolution_m) {
  if (!(std::isfinite(resolution_m) && resolution_m > 0.0)) {
    throw core::ConfigError("map_resolution: expected a finite number > 0 m, got " +
                            core::number_text(resolution_m));
  }
  const double cells = map_cell_count(world, resolution_m);
  if (!(cells <= static_cast<double>(kMaxMapCells))) {
    throw core::ConfigError(
        "map_resolution: " + core::number_text(resolution_m) + " m over the floor of world '" +
        world.name + "' (" + core::number_text(world.size.x()) + " x " +
        core::number_text(world.size.y()) + " m) gives " + core::number_text(cells) +
        " cells, more than the " + std::to_string(kMaxMapCells) + " an occupancy grid may have");
  }
}

model::OccupancyGrid rasterize_static_map(const model::WorldDescription& world,
                                          double requested_resolution_m) {
  check_map_size(world, requested_resolution_m);
  // The resolution as /map carries it (nav_msgs/OccupancyGrid holds it as float32: 0.05 m is
  // 0.0500000007 m there), so that the nodes that receive the grid and the in-process engine,
  // which does not, work on the same grid.
  const double resolution_m = static_cast<float>(requested_resolution_m);
  model::OccupancyGrid grid;
  grid.origin = world.origin;
  grid.resolution_m = resolution_m;
  grid.width = cells_along(world.size.x(), resolution_m);
  grid.height = cells_along(world.size.y(), resolution_m);
  grid.cells.assign(static_cast<size_t>(grid.width) * grid.height, model::OccupancyGrid::kFree);

  // Box2D pads every polygon with a skin of b2_polygonRadius. The cell square is shrunk by the
  // skins in play (its own, and the obstacle's unless it is a circle) so that a cell merely
  // touching an obstacle is not counted as occupied.
  auto cell_square = [resolution_m](int skins) {
    const float half = static_cast<float>(0.5 * resolution_m) - skins * b2_polygonRadius - 1e-4f;
    b2PolygonShape square;
    square.SetAsBox(std::max(half, 1e-4f), std::max(half, 1e-4f));
    return square;
  };
  const b2PolygonShape cell_near_polygon = cell_square(2);
  const b2PolygonShape cell_near_circle = cell_square(1);

  for (const model::StaticObject& object : world.objects) {
    const StaticShape shape = make_static_shape(object);
    const b2PolygonShape& cell = shape.is_circle ? cell_near_circle : cell_near_polygon;
    b2AABB box;
    shape.shape().ComputeAABB(&box, shape.transform, 0);
    int x0, y0, x1, y1;
    grid.cell_of({box.lowerBound.x, box.lowerBound.y}, x0, y0);
    grid.cell_of({box.upperBound.x, box.upperBound.y}, x1, y1);
    x0 = std::max(x0, 0);
    y0 = std::max(y0, 0);
    x1 = std::min(x1, grid.width - 1);
    y1 = std::min(y1, grid.height - 1);
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        int8_t& value = grid.cells[static_cast<size_t>(y) * grid.width + x];
        if (value == model::OccupancyGrid::kOccupied) {
          continue;
        }
        const Eigen::Vector2d c = grid.cell_centre(x, y);
        b2Transform cell_pose(b2Vec2(static_cast<float>(c.x()), static_cast<float>(c.y())),
                              b2Rot(0.0f));
        if (b2TestOverlap(&cell, 0, &shape.shape(), 0, cell_pose, shape.transform)) {
          value = model::OccupancyGrid::kOccupied;
        }
      }
    }
  }
  return grid;
}

void MapSensor::step(Object& owner, const StepContext& context) {
  if (!has_map_) {
    // Cannot throw here: the Simulation checked this world and resolution when it was built.
    map_ = rasterize_static_map(context.simulation.world(), resolution_m_);
    has_map_ = true;
  }
}

}  // namespace ari_social_sim::world
