// rendering::wall_fittings_of: rooms get the closed doors, pictures and notice boards that world
// files leave out, where nothing stands in their way; bare walls left the head camera's frames
// without the darker greys a room has (docs/cameras.md, "Walls").
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "ari_social_sim/model/world_file.hpp"
#include "ari_social_sim/rendering/doorways.hpp"
#include "ari_social_sim/rendering/wall_fittings.hpp"

namespace ari_social_sim::rendering {
namespace {

model::WorldDescription empty_room() {
  return model::load_world_file(std::string(ARI_SOURCE_DIR) + "/worlds/room_6x6.yaml");
}

std::vector<RenderPrimitive> fittings_with(const std::vector<RenderPrimitive>& furniture) {
  return wall_fittings_of(empty_room(), model::kDefaultWallHeightM, furniture);
}

Eigen::Vector3d centre_of(const RenderPrimitive& part) {
  return part.X_world_shape.translation();
}

std::vector<RenderPrimitive> door_leaves(const std::vector<RenderPrimitive>& fittings) {
  std::vector<RenderPrimitive> leaves;
  std::copy_if(fittings.begin(), fittings.end(), std::back_inserter(leaves), [](const auto& part) {
    return part.size.x() == kDoorLeafWidthM && part.size.z() == kDoorHeightM;
  });
  return leaves;
}

// The backmost part of each picture (its frame) and notice board, 2 cm deep against the wall.
std::vector<RenderPrimitive> hangings(const std::vector<RenderPrimitive>& fittings) {
  std::vector<RenderPrimitive> backs;
  std::copy_if(fittings.begin(), fittings.end(), std::back_inserter(backs), [](const auto& part) {
    return std::abs(part.size.y() - 0.02) < 1e-9 && part.size.x() >= 0.8;
  });
  return backs;
}

bool on_south_wall_at(const RenderPrimitive& part, double x) {
  return std::abs(centre_of(part).x() - x) < 1e-6 && centre_of(part).y() < 0.1;
}

// The room's walls are 6.1 m (south, north) and 5.9 m (west, east) long: less 0.4 m at each end,
// two slots each, 1.325 and 1.275 m either side of the wall's middle.
constexpr double kSouthSlots[2] = {3.0 - 1.325, 3.0 + 1.325};

TEST(WallFittings, TheEmptyRoomHasADoorInEveryOtherWallAndPicturesOnTheRest) {
  const std::vector<RenderPrimitive> fittings = fittings_with({});
  // South and west walls (the first and third in the file), each in its second slot.
  const std::vector<RenderPrimitive> leaves = door_leaves(fittings);
  ASSERT_EQ(leaves.size(), 2u);
  EXPECT_NEAR(centre_of(leaves[0]).x(), kSouthSlots[1], 1e-9);
  EXPECT_NEAR(centre_of(leaves[0]).y(), 0.0, 1e-9);
  EXPECT_NEAR(centre_of(leaves[1]).x(), 0.0, 1e-9);
  EXPECT_NEAR(centre_of(leaves[1]).y(), 3.0 + 1.275, 1e-9);
  for (const RenderPrimitive& leaf : leaves) {
    EXPECT_NEAR(leaf.size.y(), 0.1 + 2 * 0.02, 1e-9);  // through the wall, 2 cm out of each face
    EXPECT_NEAR(centre_of(leaf).z(), 0.5 * kDoorHeightM, 1e-9);
  }
  // The six other slots each get a picture or a board on the room's side, none outside.
  const std::vector<RenderPrimitive> backs = hangings(fittings);
  ASSERT_EQ(backs.size(), 6u);
  for (const RenderPrimitive& back : backs) {
    const Eigen::Vector3d centre = centre_of(back);
    EXPECT_GT(std::min(centre.x(), centre.y()), 0.05);  // inside the walls' inner faces
    EXPECT_LT(std::max(centre.x(), centre.y()), 5.95);
    EXPECT_NEAR(centre.z(), kHangingCentreM, 1e-9);
  }
  const auto boards = std::count_if(backs.begin(), backs.end(),
                                    [](const auto& back) { return back.size.x() == 1.2; });
  EXPECT_EQ(boards, 2);  // one in three
}

TEST(WallFittings, NoDoorOpensOntoChairsButAPictureHangsAboveThem) {
  // A row of chairs, 0.75 m high, along the south wall where its door would be.
  const RenderPrimitive chairs = solid(PrimitiveShape::kBox, upright_pose({4.3, 0.3}, 0.375, 0.0),
                                       {2.0, 0.45, 0.75}, {0.2f, 0.3f, 0.5f});
  const std::vector<RenderPrimitive> fittings = fittings_with({chairs});
  const std::vector<RenderPrimitive> leaves = door_leaves(fittings);
  ASSERT_EQ(leaves.size(), 1u);  // the west wall's
  EXPECT_NEAR(centre_of(leaves[0]).x(), 0.0, 1e-9);
  const std::vector<RenderPrimitive> backs = hangings(fittings);
  const auto above = std::find_if(backs.begin(), backs.end(), [](const auto& back) {
    return on_south_wall_at(back, kSouthSlots[1]);
  });
  ASSERT_NE(above, backs.end());
  EXPECT_GT(centre_of(*above).z() - 0.5 * above->size.z(), 0.75);  // its bottom over the backs
  EXPECT_EQ(backs.size(), 7u);
}

TEST(WallFittings, NothingHangsBehindAPlant) {
  // A plant 1.25 m high in front of the south wall's first slot, its leaves 0.3 m out.
  const RenderPrimitive plant =
      solid(PrimitiveShape::kCylinder, upright_pose({kSouthSlots[0] + 0.3, 0.45}, 0.625, 0.0),
            {0.6, 0.6, 1.25}, {0.2f, 0.45f, 0.18f});
  const std::vector<RenderPrimitive> backs = hangings(fittings_with({plant}));
  EXPECT_EQ(backs.size(), 5u);
  EXPECT_TRUE(std::none_of(backs.begin(), backs.end(), [](const auto& back) {
    return on_south_wall_at(back, kSouthSlots[0]);
  }));
}

}  // namespace
}  // namespace ari_social_sim::rendering
