// rendering::furniture_of: the waiting room's chairs, tables and plants drawn as such, within
// the footprints the physics collides with.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "ari_social_sim/model/world_file.hpp"
#include "ari_social_sim/rendering/furniture.hpp"

namespace ari_social_sim::rendering {
namespace {

const model::WorldDescription& waiting_room() {
  static const model::WorldDescription world =
      model::load_world_file(std::string(ARI_SOURCE_DIR) + "/worlds/hospital_waiting_room.yaml");
  return world;
}

const model::StaticObject& object_named(const std::string& name) {
  for (const model::StaticObject& object : waiting_room().objects) {
    if (object.name == name) {
      return object;
    }
  }
  throw std::runtime_error("no object " + name);
}

// The tallest part's centre: a chair's backrest.
const RenderPrimitive& highest_part(const std::vector<RenderPrimitive>& parts) {
  const RenderPrimitive* highest = &parts.front();
  for (const RenderPrimitive& part : parts) {
    if (part.X_world_shape.translation().z() + 0.5 * part.size.z() >
        highest->X_world_shape.translation().z() + 0.5 * highest->size.z()) {
      highest = &part;
    }
  }
  return *highest;
}

TEST(Furniture, ChairsTurnTheirBacksToTheWallOrTheRowBehind) {
  // West-wall chairs face east, north-wall chairs south; the middle rows sit back to back.
  const std::pair<std::string, Eigen::Vector2d> expected[] = {{"chair w3", {-1, 0}},
                                                              {"chair n2", {0, 1}},
                                                              {"chair row south", {0, 1}},
                                                              {"chair row north", {0, -1}}};
  for (const auto& [name, back] : expected) {
    const model::StaticObject& chair = object_named(name);
    const std::optional<std::vector<RenderPrimitive>> parts =
        furniture_of(chair, model::kDefaultFurnitureHeightM, waiting_room());
    ASSERT_TRUE(parts.has_value()) << name;
    const Eigen::Vector2d backrest = highest_part(*parts).X_world_shape.translation().head<2>();
    const Eigen::Vector2d towards = (backrest - chair.pose.position).normalized();
    EXPECT_GT(towards.dot(back), 0.99) << name << ": backrest towards " << towards.transpose();
  }
  // A row of 3 m is six seats with four legs each, and one backrest.
  EXPECT_EQ(furniture_of(object_named("chair row south"), 0.75, waiting_room())->size(), 31u);
}

TEST(Furniture, PartsStayInTheFootprintThePhysicsCollidesWith) {
  for (const model::StaticObject& object : waiting_room().objects) {
    const std::optional<std::vector<RenderPrimitive>> parts =
        furniture_of(object, model::kDefaultFurnitureHeightM, waiting_room());
    if (!parts) {
      continue;
    }
    for (const RenderPrimitive& part : *parts) {
      // Each part's centre lies over the footprint (in the object's frame).
      const Eigen::Vector2d local =
          Eigen::Rotation2Dd(-object.pose.theta) *
          (part.X_world_shape.translation().head<2>() - object.pose.position);
      if (object.type == model::ShapeType::kCircle) {
        EXPECT_LE(local.norm(), object.radius_m) << object.name;
      } else {
        EXPECT_LE(std::abs(local.x()), 0.5 * object.size.x() + 1e-9) << object.name;
        EXPECT_LE(std::abs(local.y()), 0.5 * object.size.y() + 1e-9) << object.name;
      }
    }
  }
  // Other objects stay blocks.
  EXPECT_FALSE(furniture_of(object_named("information stand"), 0.75, waiting_room()).has_value());
  EXPECT_FALSE(furniture_of(object_named("north wall"), 2.5, waiting_room()).has_value());
}

TEST(Furniture, TheReceptionDeskHasAWorkTopAndALedgeOnTheVisitorsSide) {
  // The desk (9.4, 1.6), 2.6 x 0.7, has the south wall 1.25 m behind it and the room in front:
  // the staff sit on its south side, visitors stand on its north side.
  const std::optional<std::vector<RenderPrimitive>> parts =
      furniture_of(object_named("reception desk"), 0.75, waiting_room());
  ASSERT_TRUE(parts.has_value());
  const RenderPrimitive& ledge_top = highest_part(*parts);
  EXPECT_NEAR(ledge_top.X_world_shape.translation().z() + 0.5 * ledge_top.size.z(), 1.13, 1e-9);
  // The ledge runs the desk's length on its north edge, 0.3 m deep.
  EXPECT_NEAR(ledge_top.size.x(), 2.6, 1e-9);
  EXPECT_NEAR(ledge_top.size.y(), 0.3, 1e-9);
  EXPECT_NEAR(ledge_top.X_world_shape.translation().y(), 1.6 + 0.35 - 0.15, 1e-9);
  // The work top covers the whole footprint at the desk's height.
  const bool work_top = std::any_of(parts->begin(), parts->end(), [](const RenderPrimitive& p) {
    return p.surface == Surface::kWood &&
           std::abs(p.X_world_shape.translation().z() - 0.735) < 1e-9 &&
           std::abs(p.size.y() - 0.7) < 1e-9;
  });
  EXPECT_TRUE(work_top);
}

}  // namespace
}  // namespace ari_social_sim::rendering
