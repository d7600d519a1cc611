// physics_primitives: ARI's links and the physics' people as render primitives.

#include <gtest/gtest.h>

#include "ari_social_sim/rendering/physics_primitives.hpp"

namespace ari_social_sim::rendering {
namespace {

TEST(PhysicsPrimitives, EveryVisualOfAriAtItsLinksPose) {
  const physics::RobotModel model = physics::RobotModel::from_urdf_file(ARI_URDF);
  const std::unordered_map<std::string, double> q = {{"head_1_joint", 0.4}};
  std::vector<Eigen::Isometry3d> poses = model.link_poses(q);
  size_t visuals = 0;
  for (const physics::RobotLink& link : model.links()) {
    visuals += link.visuals.size();
  }
  const std::vector<RenderPrimitive> primitives = robot_primitives(model, poses);
  // Every visual but the two 1 mm dummy finger spheres.
  EXPECT_EQ(primitives.size(), visuals - 2);
  // head_1_link's box (0.15 x 0.12 x 0.124 at z 0.118 in the link) turned 0.4 rad with the pan.
  const int head = model.link_index("head_1_link");
  const Eigen::Vector3d centre =
      poses[static_cast<size_t>(head)] * Eigen::Vector3d(0.0, 0.0, 0.118);
  const auto found = std::find_if(primitives.begin(), primitives.end(), [&](const auto& p) {
    return (p.X_world_shape.translation() - centre).norm() < 1e-9;
  });
  ASSERT_NE(found, primitives.end());
  EXPECT_TRUE(found->size.isApprox(Eigen::Vector3d(0.15, 0.12, 0.124)));
  EXPECT_NEAR(std::atan2(found->X_world_shape.linear()(1, 0), found->X_world_shape.linear()(0, 0)),
              0.4, 1e-9);
}

}  // namespace
}  // namespace ari_social_sim::rendering
