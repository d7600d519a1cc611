#include "ari_social_sim/world/box2d_shapes.hpp"

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/model/shape_geometry.hpp"

namespace ari_social_sim::world {

// The model's shape rules are written for this Box2D: its slop and its largest polygon.
static_assert(static_cast<float>(model::kMinShapeFeatureM) == b2_linearSlop);
static_assert(model::kMaxPolygonVertices == b2_maxPolygonVertices);

StaticShape make_static_shape(const model::StaticObject& object) {
  // Box2D asserts (aborts the process) on a shape it cannot build; refuse it with a message.
  const std::string defect = model::static_object_defect(object);
  if (!defect.empty()) {
    throw core::ConfigError("object " + std::to_string(object.id) + " ('" + object.name +
                            "'): expected a shape Box2D can build, got " + defect);
  }
  StaticShape result;
  result.transform.SetIdentity();
  switch (object.type) {
    case model::ShapeType::kWall:
    case model::ShapeType::kBox:
      result.polygon.SetAsBox(static_cast<float>(0.5 * object.size.x()),
                              static_cast<float>(0.5 * object.size.y()));
      result.transform.Set(b2Vec2(static_cast<float>(object.pose.position.x()),
                                  static_cast<float>(object.pose.position.y())),
                           static_cast<float>(object.pose.theta));
      break;
    case model::ShapeType::kCircle:
      result.is_circle = true;
      result.circle.m_radius = static_cast<float>(object.radius_m);
      result.transform.Set(b2Vec2(static_cast<float>(object.pose.position.x()),
                                  static_cast<float>(object.pose.position.y())),
                           0.0f);
      break;
    case model::ShapeType::kPolygon: {
      b2Vec2 vertices[b2_maxPolygonVertices];
      for (size_t i = 0; i < object.points.size(); ++i) {
        vertices[i].Set(static_cast<float>(object.points[i].x()),
                        static_cast<float>(object.points[i].y()));
      }
      result.polygon.Set(vertices, static_cast<int32>(object.points.size()));
      break;
    }
  }
  return result;
}

}  // namespace ari_social_sim::world
