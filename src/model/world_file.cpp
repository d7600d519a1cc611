#include "ari_social_sim/model/world_file.hpp"

#include <cmath>
#include <set>
#include <sstream>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/number_text.hpp"

namespace ari_social_sim::model {
namespace {

// Ids given automatically to static objects start here, away from the small ids people give to
// humans and ARI in scene files.
constexpr ObjectId kFirstAutomaticStaticId = 1000;

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// True if the vertices form a strictly convex polygon in either winding.
bool is_convex(const std::vector<Eigen::Vector2d>& points) {
  int sign = 0;
  const size_t n = points.size();
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d edge = points[(i + 1) % n] - points[i];
    const Eigen::Vector2d next = points[(i + 2) % n] - points[(i + 1) % n];
    const double turn = cross(edge, next);
    if (std::abs(turn) < 1e-9) {
      return false;
    }
    const int s = turn > 0 ? 1 : -1;
    if (sign != 0 && s != sign) {
      return false;
    }
    sign = s;
  }
  return true;
}

// Coordinates and extents in a world file: finite (YamlMap's numbers always are) and bounded.
const core::Bounds kCoordinate = core::between(-kMaxWorldCoordinateM, kMaxWorldCoordinateM);
const core::Bounds kExtent{0.0, kMaxWorldSideM, true};

StaticObject parse_object(const core::YamlMap& entry) {
  StaticObject object;
  const std::string type = entry.required<std::string>("type");
  object.id = entry.optional<unsigned>("id", kNoObject, core::positive());
  object.name = entry.optional<std::string>("name", "");
  if (type == "wall") {
    object.type = ShapeType::kWall;
    const Eigen::Vector2d from = entry.required<Eigen::Vector2d>("from", kCoordinate);
    const Eigen::Vector2d to = entry.required<Eigen::Vector2d>("to", kCoordinate);
    const double thickness = entry.optional<double>("thickness", 0.1, kExtent);
    const double length = (to - from).norm();
    if (length < 1e-6) {
      entry.fail("to", "a point different from 'from' (a wall needs a length)",
                 "the same point as 'from'");
    }
    object.pose.position = 0.5 * (from + to);
    object.pose.theta = std::atan2(to.y() - from.y(), to.x() - from.x());
    object.size = {length, thickness};
  } else if (type == "box") {
    object.type = ShapeType::kBox;
    object.pose.position = entry.required<Eigen::Vector2d>("position", kCoordinate);
    object.pose.theta = entry.optional<double>("orientation", 0.0);
    object.size = entry.required<Eigen::Vector2d>("size", kExtent);
  } else if (type == "circle") {
    object.type = ShapeType::kCircle;
    object.pose.position = entry.required<Eigen::Vector2d>("position", kCoordinate);
    object.radius_m = entry.required<double>("radius", kExtent);
  } else if (type == "polygon") {
    object.type = ShapeType::kPolygon;
    object.points = entry.required<std::vector<Eigen::Vector2d>>("points", kCoordinate);
    // Box2D takes convex polygons of at most 8 vertices; larger furniture is several objects.
    if (object.points.size() < 3 || object.points.size() > 8 || !is_convex(object.points)) {
      entry.fail(
          "points", "3 to 8 vertices of a convex polygon",
          std::to_string(object.points.size()) + " vertices" +
              (object.points.size() >= 3 && object.points.size() <= 8 ? ", not convex" : ""));
    }
    Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
    for (const Eigen::Vector2d& p : object.points) {
      centroid += p;
    }
    object.pose.position = centroid / static_cast<double>(object.points.size());
  } else {
    entry.fail("type", "one of wall, box, circle, polygon", "'" + type + "'");
  }
  object.height_m = entry.optional<double>(
      "height", type == "wall" ? kDefaultWallHeightM : kDefaultFurnitureHeightM, kExtent);
  entry.finish();
  return object;
}

}  // namespace

bool WorldDescription::contains(const Eigen::Vector2d& point) const {
  return point.x() >= origin.x() && point.y() >= origin.y() && point.x() <= origin.x() + size.x() &&
         point.y() <= origin.y() + size.y();
}

void WorldDescription::validate() const {
  const std::string where = "world '" + name + "': ";
  for (int axis = 0; axis < 2; ++axis) {
    const char* suffix = axis == 0 ? ".x" : ".y";
    if (!(std::abs(origin[axis]) <= kMaxWorldCoordinateM)) {
      throw core::ConfigError(where + "origin" + suffix + ": expected a finite number in [" +
                              core::number_text(-kMaxWorldCoordinateM) + ", " +
                              core::number_text(kMaxWorldCoordinateM) + "] m, got " +
                              core::number_text(origin[axis]));
    }
    if (!(size[axis] > 0.0 && size[axis] <= kMaxWorldSideM)) {
      throw core::ConfigError(where + "size" + suffix + ": expected a finite number in (0, " +
                              core::number_text(kMaxWorldSideM) + "] m, got " +
                              core::number_text(size[axis]));
    }
  }
  if (objects.size() > kMaxWorldObjects) {
    throw core::ConfigError(where + "objects: expected at most " +
                            std::to_string(kMaxWorldObjects) + " objects, got " +
                            std::to_string(objects.size()));
  }
}

WorldDescription parse_world(const core::YamlMap& root) {
  WorldDescription world;
  world.name = root.required<std::string>("name");
  world.origin = root.optional<Eigen::Vector2d>("origin", Eigen::Vector2d::Zero(), kCoordinate);
  world.size = root.required<Eigen::Vector2d>("size", {0.0, kMaxWorldSideM, true});
  std::set<ObjectId> ids;
  ObjectId next_id = kFirstAutomaticStaticId;
  const std::vector<core::YamlMap> entries = root.list("objects");
  if (entries.size() > kMaxWorldObjects) {
    root.fail("objects", "at most " + std::to_string(kMaxWorldObjects) + " objects",
              std::to_string(entries.size()));
  }
  for (const core::YamlMap& entry : entries) {
    StaticObject object = parse_object(entry);
    if (object.id != kNoObject && !ids.insert(object.id).second) {
      entry.fail("id", "an id used by no other object", std::to_string(object.id));
    }
    world.objects.push_back(std::move(object));
  }
  // Automatic ids skip the ones given explicitly, so adding an id to one object never renumbers
  // the others.
  for (StaticObject& object : world.objects) {
    if (object.id == kNoObject) {
      while (ids.count(next_id) > 0) {
        ++next_id;
      }
      object.id = next_id;
      ids.insert(next_id);
    }
  }
  root.finish();
  return world;
}

WorldDescription load_world_file(const std::string& path) {
  return parse_world(core::YamlMap::load_file(path));
}

}  // namespace ari_social_sim::model
