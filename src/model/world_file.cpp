#include "ari_social_sim/model/world_file.hpp"

#include <cmath>
#include <set>

#include "ari_social_sim/core/config_check.hpp"
#include "ari_social_sim/core/config_reader.hpp"
#include "ari_social_sim/core/error.hpp"

namespace ari_social_sim::model {
namespace {

// Ids given automatically to static objects start here, away from the small ids people give to
// humans and ARI in scene files.
constexpr ObjectId kFirstAutomaticStaticId = 1000;

}  // namespace

std::string WorldObjectEntry::shape_mismatch() const {
  const bool wall = type == ShapeType::kWall, box = type == ShapeType::kBox,
             circle = type == ShapeType::kCircle, polygon = type == ShapeType::kPolygon;
  // Each key: given or not, whether this type has it, whether it must then be given.
  const struct {
    const char* key;
    bool given, belongs, required;
  } keys[] = {{"from", from.has_value(), wall, true},
              {"to", to.has_value(), wall, true},
              {"thickness", thickness.has_value(), wall, false},
              {"position", position.has_value(), box || circle, true},
              {"orientation", orientation.has_value(), box, false},
              {"size", size.has_value(), box, true},
              {"radius", radius.has_value(), circle, true},
              {"points", points.has_value(), polygon, true}};
  const std::string shape = std::string("a ") + core::choice_name(type, kShapeTypes);
  for (const auto& k : keys) {
    if (k.belongs && k.required && !k.given) {
      return shape + " without " + k.key;
    }
    if (!k.belongs && k.given) {
      return shape + " with " + k.key;
    }
  }
  return "";
}

StaticObject WorldObjectEntry::object() const {
  StaticObject object;
  object.id = id;
  object.name = name;
  object.type = type;
  switch (type) {
    case ShapeType::kWall: {
      const double length = (*to - *from).norm();
      object.pose.position = 0.5 * (*from + *to);
      object.pose.theta = std::atan2(to->y() - from->y(), to->x() - from->x());
      object.size = {length, thickness.value_or(kDefaultWallThicknessM)};
      break;
    }
    case ShapeType::kBox:
      object.pose.position = *position;
      object.pose.theta = orientation.value_or(0.0);
      object.size = *size;
      break;
    case ShapeType::kCircle:
      object.pose.position = *position;
      object.radius_m = *radius;
      break;
    case ShapeType::kPolygon: {
      object.points = *points;
      Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
      for (const Eigen::Vector2d& p : object.points) {
        centroid += p;
      }
      object.pose.position = centroid / static_cast<double>(object.points.size());
      break;
    }
  }
  object.height_m =
      height.value_or(type == ShapeType::kWall ? kDefaultWallHeightM : kDefaultFurnitureHeightM);
  return object;
}

std::optional<ObjectId> WorldFile::repeated_id() const {
  std::set<ObjectId> ids;
  for (const WorldObjectEntry& entry : objects) {
    if (entry.id != kNoObject && !ids.insert(entry.id).second) {
      return entry.id;
    }
  }
  return std::nullopt;
}

WorldDescription WorldFile::description() const {
  WorldDescription world;
  world.name = name;
  world.origin = origin;
  world.size = size;
  std::set<ObjectId> ids;
  for (const WorldObjectEntry& entry : objects) {
    world.objects.push_back(entry.object());
    ids.insert(entry.id);
  }
  // Automatic ids skip the ones given explicitly, so adding an id to one object never renumbers
  // the others.
  ObjectId next_id = kFirstAutomaticStaticId;
  for (StaticObject& object : world.objects) {
    if (object.id == kNoObject) {
      while (ids.count(next_id) > 0) {
        ++next_id;
      }
      object.id = next_id;
      ids.insert(next_id);
    }
  }
  return world;
}

bool WorldDescription::contains(const Eigen::Vector2d& point) const {
  return point.x() >= origin.x() && point.y() >= origin.y() && point.x() <= origin.x() + size.x() &&
         point.y() <= origin.y() + size.y();
}

void WorldDescription::validate() const {
  // The file's bounds, without the objects (built in code, they are StaticObjects).
  WorldFile extent;
  extent.name = name;
  extent.origin = origin;
  extent.size = size;
  core::check_fields(extent, "world '" + name + "'");
  if (objects.size() > kMaxWorldObjects) {
    throw core::ConfigError("world '" + name + "': objects: expected at most " +
                            std::to_string(kMaxWorldObjects) + " objects, got " +
                            std::to_string(objects.size()));
  }
  // Objects built in code (learning tasks, tests) meet the file's geometry rules too: whatever
  // reaches Box2D must be a shape it can build.
  for (size_t i = 0; i < objects.size(); ++i) {
    const std::string defect = static_object_defect(objects[i]);
    if (!defect.empty()) {
      throw core::ConfigError("world '" + name + "': objects[" + std::to_string(i) + "] ('" +
                              objects[i].name + "'): expected a shape Box2D can build (" +
                              polygon_expectation() + "; sides and radii at least " +
                              core::number_text(kMinShapeFeatureM) + " m), got " + defect);
    }
  }
}

WorldDescription parse_world(const core::YamlMap& root) {
  return core::read_fields<WorldFile>(root).description();
}

WorldDescription load_world_file(const std::string& path) {
  return parse_world(core::YamlMap::load_file(path));
}

}  // namespace ari_social_sim::model
