#pragma once

namespace ari_social_sim::nodes {

// The frames every node names: the map and the odometry frame (REP-105) and ARI's base
// (ari_robot's URDF).
inline constexpr char kMapFrame[] = "map";
inline constexpr char kOdomFrame[] = "odom";
inline constexpr char kBaseFrame[] = "base_footprint";
// ARI's head joints (pan, tilt), as its controllers and /joint_states name them.
inline constexpr char kHeadPanJoint[] = "head_1_joint";
inline constexpr char kHeadTiltJoint[] = "head_2_joint";
// ARI's other moving joints (urdf/ari.urdf), which the 2D body never moves: world_node reports
// them at rest (wheels and casters unturned, arms down, hands open), so that
// robot_state_publisher can place every link of the robot model.
inline constexpr const char* kJointsAtRest[] = {
    "wheel_right_joint",         "wheel_left_joint",           "caster_right_joint",
    "caster_left_joint",         "arm_left_1_joint",           "arm_left_2_joint",
    "arm_left_3_joint",          "arm_left_4_joint",           "hand_left_fingers_joint",
    "hand_left_virtual_1_joint", "hand_left_virtual_2_joint",  "arm_right_1_joint",
    "arm_right_2_joint",         "arm_right_3_joint",          "arm_right_4_joint",
    "hand_right_fingers_joint",  "hand_right_virtual_1_joint", "hand_right_virtual_2_joint"};

}  // namespace ari_social_sim::nodes
