#include "ari_social_sim/perception/sound_map.hpp"

#include <algorithm>

#include "ari_social_sim/world/map_sensor.hpp"

namespace ari_social_sim::perception {

world::OccupancyGrid rasterize_walls(const world::WorldDescription& world, double resolution_m) {
  world::WorldDescription walls = world;
  walls.objects.erase(std::remove_if(walls.objects.begin(), walls.objects.end(),
                                     [](const world::StaticObject& object) {
                                       return object.type != world::ShapeType::kWall;
                                     }),
                      walls.objects.end());
  return world::rasterize_static_map(walls, resolution_m);
}

}  // namespace ari_social_sim::perception
