// RobotModel: urdf/ari.urdf read with urdfdom, checked against ari_robot's numbers.

#include <gtest/gtest.h>

#include <cstdio>
#include <memory>

#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/physics/robot_model.hpp"

namespace ari_social_sim::physics {
namespace {

const RobotModel& ari() {
  static const RobotModel model = RobotModel::from_urdf_file(ARI_URDF);
  return model;
}

TEST(RobotModel, CheckUrdfAcceptsTheFile) {
  // urdfdom's own command-line checker, as a user would run it.
  const std::string command = std::string("check_urdf ") + ARI_URDF + " 2>&1";
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  ASSERT_NE(pipe, nullptr);
  std::string output;
  char buffer[256];
  while (fgets(buffer, sizeof(buffer), pipe.get()) != nullptr) {
    output += buffer;
  }
  EXPECT_EQ(pclose(pipe.release()), 0) << output;
  EXPECT_NE(output.find("Successfully Parsed XML"), std::string::npos) << output;
  EXPECT_NE(output.find("root Link: base_footprint"), std::string::npos) << output;
}

TEST(RobotModel, HasAriV1Joints) {
  // 2 wheels + 2 casters + 2 head + 2 x 4 arm + 2 fingers + 2 x 2 virtual fingers = 20.
  EXPECT_EQ(ari().movable_joint_names().size(), 20u);
  const RobotJoint& pan = ari().joint("head_1_joint");
  EXPECT_DOUBLE_EQ(pan.upper_rad, 1.309);
  EXPECT_DOUBLE_EQ(pan.max_velocity_rps, 3.0);
  EXPECT_DOUBLE_EQ(ari().joint("head_2_joint").lower_rad, -0.262);
  EXPECT_NEAR(ari().joint("arm_left_2_joint").upper_rad, 155.0 * M_PI / 180.0, 1e-6);
  EXPECT_NEAR(ari().joint("hand_right_fingers_joint").upper_rad, 75.0 * M_PI / 180.0, 1e-6);
  EXPECT_DOUBLE_EQ(ari().joint("arm_right_3_joint").max_effort_nm, 5.0);
  EXPECT_EQ(ari().joint("wheel_left_joint").type, JointType::kContinuous);
  EXPECT_EQ(ari().link_index("torso_link"), -1);  // ARI has none (ari_robot's URDF)
}

TEST(RobotModel, MassesAddUpToAri) {
  // ari_robot: the summed URDF mass is about 54.9 kg.
  double total = 0.0;
  for (const RobotLink& link : ari().links()) {
    total += link.inertia.mass_kg;
  }
  EXPECT_NEAR(total, 54.9, 0.5);
  EXPECT_DOUBLE_EQ(
      ari().links()[static_cast<size_t>(ari().link_index("base_link"))].inertia.mass_kg, 43.407);
}

struct FramePosition {
  const char* frame;
  double x, y, z;
};

class ZeroPose : public ::testing::TestWithParam<FramePosition> {};

// ari_robot's URDF: frame positions in base_footprint at the zero pose, given to the millimetre.
TEST_P(ZeroPose, FrameSitsWhereAriHasIt) {
  const FramePosition& expected = GetParam();
  const Eigen::Vector3d p = ari().link_pose(expected.frame, {}).translation();
  EXPECT_NEAR(p.x(), expected.x, 0.003) << expected.frame;
  EXPECT_NEAR(p.y(), expected.y, 0.003) << expected.frame;
  EXPECT_NEAR(p.z(), expected.z, 0.003) << expected.frame;
}

INSTANTIATE_TEST_SUITE_P(
    AriV1, ZeroPose,
    ::testing::Values(FramePosition{"base_link", 0, 0, 0.125},
                      FramePosition{"head_1_link", -0.2255, 0, 1.3165},
                      FramePosition{"head_2_link", -0.183, 0, 1.4095},
                      FramePosition{"sellion_link", -0.143, 0, 1.502},
                      FramePosition{"head_front_camera_link", -0.120, 0, 1.591},
                      FramePosition{"head_front_camera_color_optical_frame", -0.120, 0, 1.591},
                      FramePosition{"arm_left_1_link", -0.219, 0.098, 1.236},
                      FramePosition{"arm_right_1_link", -0.219, -0.098, 1.236},
                      FramePosition{"arm_left_4_link", -0.219, 0.207, 1.005},
                      FramePosition{"arm_right_4_link", -0.219, -0.207, 1.005},
                      FramePosition{"arm_left_tool_link", -0.219, 0.208, 0.652},
                      FramePosition{"arm_right_tool_link", -0.219, -0.208, 0.652},
                      FramePosition{"wheel_left_link", 0, 0.22, 0.125},
                      FramePosition{"caster_right_link", -0.455, -0.1025, 0.045},
                      FramePosition{"torso_front_camera_link", -0.104, 0.018, 1.105},
                      FramePosition{"torso_mic_front_link", -0.122, 0, 0.928}),
    [](const ::testing::TestParamInfo<FramePosition>& info) {
      return std::string(info.param.frame);
    });

TEST(RobotModel, OpticalFrameFollowsRep103) {
  // Optical frame: z forward (base x), x right (base -y), y down (base -z).
  const Eigen::Matrix3d R = ari().link_pose("head_front_camera_color_optical_frame", {}).linear();
  EXPECT_TRUE(R.col(2).isApprox(Eigen::Vector3d::UnitX(), 1e-9)) << R;
  EXPECT_TRUE(R.col(0).isApprox(-Eigen::Vector3d::UnitY(), 1e-9)) << R;
  EXPECT_TRUE(R.col(1).isApprox(-Eigen::Vector3d::UnitZ(), 1e-9)) << R;
  // The torso RGB-D camera looks 42.5 degrees down: its optical z has z = -sin(42.5 deg).
  const Eigen::Matrix3d T = ari().link_pose("torso_front_camera_color_optical_frame", {}).linear();
  EXPECT_NEAR(T.col(2).z(), -std::sin(42.5 * M_PI / 180.0), 1e-9);
}

TEST(RobotModel, PositiveHeadAnglesLookLeftAndDown) {
  // ari_robot's URDF: head_1 positive turns left, head_2 positive tilts down.
  const Eigen::Vector3d left =
      ari().link_pose("head_front_camera_link", {{"head_1_joint", 0.5}}).linear().col(0);
  EXPECT_NEAR(std::atan2(left.y(), left.x()), 0.5, 1e-9);
  const Eigen::Vector3d down =
      ari().link_pose("head_front_camera_link", {{"head_2_joint", 0.3}}).linear().col(0);
  EXPECT_NEAR(std::asin(-down.z()), 0.3, 1e-9);
}

TEST(RobotModel, ArmsMirrorEachOther) {
  // The same positive angles give mirrored motions: left y = -right y, same x and z.
  const std::unordered_map<std::string, double> q = {
      {"arm_left_1_joint", 0.4},   {"arm_left_2_joint", 0.7},  {"arm_left_3_joint", -0.3},
      {"arm_left_4_joint", 1.1},   {"arm_right_1_joint", 0.4}, {"arm_right_2_joint", 0.7},
      {"arm_right_3_joint", -0.3}, {"arm_right_4_joint", 1.1}};
  const Eigen::Vector3d left = ari().link_pose("arm_left_tool_link", q).translation();
  const Eigen::Vector3d right = ari().link_pose("arm_right_tool_link", q).translation();
  EXPECT_NEAR(left.x(), right.x(), 1e-6);
  EXPECT_NEAR(left.y(), -right.y(), 1e-6);
  EXPECT_NEAR(left.z(), right.z(), 1e-6);
  // arm_4 positive bends the elbow so the forearm comes forward: the palm moves to +x.
  EXPECT_GT(ari().link_pose("arm_left_tool_link", {{"arm_left_4_joint", 1.0}}).translation().x(),
            -0.219 + 0.2);
}

TEST(RobotModel, RejectsWhatItCannotSimulate) {
  try {
    RobotModel::from_urdf_string("<robot name='x'><link name='a'/>", "broken.urdf");
    FAIL() << "accepted a broken URDF";
  } catch (const core::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("broken.urdf"), std::string::npos) << e.what();
  }
  const std::string prismatic =
      "<robot name='x'><link name='a'/><link name='b'/><joint name='slide' type='prismatic'>"
      "<parent link='a'/><child link='b'/><limit lower='0' upper='1' effort='1' velocity='1'/>"
      "</joint></robot>";
  try {
    RobotModel::from_urdf_string(prismatic, "slide.urdf");
    FAIL() << "accepted a prismatic joint";
  } catch (const core::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("slide.urdf: joint slide"), std::string::npos) << e.what();
  }
}

TEST(RobotModel, UrdfFileIsCheckedBeforeItIsRead) {
  // A directory given as ari_physics_node's ~urdf is an error naming it, not an abort.
  try {
    RobotModel::from_urdf_file(::testing::TempDir());
    FAIL() << "accepted a directory";
  } catch (const core::ConfigError& e) {
    EXPECT_EQ(std::string(e.what()),
              ::testing::TempDir() + ": expected a URDF file, got a directory");
  }
  EXPECT_THROW(RobotModel::from_urdf_file("/dev/zero"), core::ConfigError);
}

}  // namespace
}  // namespace ari_social_sim::physics
