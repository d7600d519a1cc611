// MultibodyLayout: ARI's URDF grouped into rigid bodies for Featherstone's algorithm.

#include <gtest/gtest.h>

#include "ari_social_sim/physics/multibody_layout.hpp"

namespace ari_social_sim::physics {
namespace {

TEST(MultibodyLayout, OneBodyPerMovableJointPlusTheBase) {
  const RobotModel model = RobotModel::from_urdf_file(ARI_URDF);
  const MultibodyLayout layout = MultibodyLayout::of(model);
  EXPECT_EQ(layout.bodies().size(), 21u);  // 20 movable joints + the base
  // Every body's parent comes before it.
  for (size_t k = 1; k < layout.bodies().size(); ++k) {
    EXPECT_LT(layout.bodies()[k].parent_body, static_cast<int>(k));
  }
  // The base carries base_link (43.407), the torso camera (0.564) and both arm bases (2 x 0.417).
  EXPECT_NEAR(layout.bodies()[0].mass_kg, 43.407 + 0.564 + 2 * 0.417, 1e-9);
  // The optical frame rides on head_2's body, 0.182 m up and 0.0634 m ahead of the tilt axis.
  const int optical = model.link_index("head_front_camera_color_optical_frame");
  const LinkPlacement& placement = layout.placements()[static_cast<size_t>(optical)];
  EXPECT_EQ(placement.body, layout.body_of_joint(model.joint_index("head_2_joint")));
  EXPECT_NEAR(placement.X_reference_link.translation().x(), 0.0634, 1e-9);
  EXPECT_NEAR(placement.X_reference_link.translation().y(), 0.182, 1e-9);
}

TEST(MultibodyLayout, MergedInertiaUsesTheParallelAxisTheorem) {
  // Two 1 kg point-like links 1 m apart on x, fixed together: the centre of mass is halfway and
  // the inertia about z is 2 x 1 kg x (0.5 m)^2 = 0.5 kg m^2 (plus their own tiny inertias).
  const std::string urdf =
      "<robot name='dumbbell'>"
      "<link name='a'><inertial><mass value='1'/><inertia ixx='1e-4' iyy='1e-4' izz='1e-4' "
      "ixy='0' ixz='0' iyz='0'/></inertial></link>"
      "<link name='b'><inertial><mass value='1'/><inertia ixx='1e-4' iyy='1e-4' izz='1e-4' "
      "ixy='0' ixz='0' iyz='0'/></inertial></link>"
      "<joint name='j' type='fixed'><parent link='a'/><child link='b'/>"
      "<origin xyz='1 0 0'/></joint></robot>";
  const MultibodyLayout layout =
      MultibodyLayout::of(RobotModel::from_urdf_string(urdf, "dumbbell.urdf"));
  ASSERT_EQ(layout.bodies().size(), 1u);
  const BodyLayout& body = layout.bodies()[0];
  EXPECT_NEAR(body.mass_kg, 2.0, 1e-12);
  EXPECT_NEAR(body.X_reference_com.translation().x(), 0.5, 1e-12);
  // Principal moments sorted ascending: about x only the own inertias, about y and z 0.5 more.
  EXPECT_NEAR(body.principal_inertia_kgm2(0), 2e-4, 1e-9);
  EXPECT_NEAR(body.principal_inertia_kgm2(2), 0.5 + 2e-4, 1e-9);
}

}  // namespace
}  // namespace ari_social_sim::physics
