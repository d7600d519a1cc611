#pragma once

#include <box2d/box2d.h>

#include "ari_social_sim/model/world_description.hpp"

namespace ari_social_sim::world {

/// A static object's Box2D shape and where it stands, shared by the physics world and the map
/// rasteriser so the two can never disagree.
struct StaticShape {
  b2PolygonShape polygon;
  b2CircleShape circle;
  bool is_circle{false};
  b2Transform transform;

  const b2Shape& shape() const {
    return is_circle ? static_cast<const b2Shape&>(circle) : static_cast<const b2Shape&>(polygon);
  }
};

StaticShape make_static_shape(const model::StaticObject& object);

}  // namespace ari_social_sim::world
