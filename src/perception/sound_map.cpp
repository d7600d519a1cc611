#include "ari_social_sim/perception/sound_map.hpp"

#include <algorithm>

#include "ari_social_sim/world/map_sensor.hpp"

namespace ari_social_sim::perception {

model::OccupancyGrid rasterize_walls(const model::WorldDescription& world, double resolution_m) {
  model::WorldDescription walls = world;
  walls.objects.erase(std::remove_if(walls.objects.begin(), walls.objects.end(),
                                     [](const model::StaticObject& object) {
                                       return object.type != model::ShapeType::kWall;
                                     }),
                      walls.objects.end());
  return world::rasterize_static_map(walls, resolution_m);
}

}  // namespace ari_social_sim::perception
