#pragma once

#include <string>
#include <vector>

#include "ari_social_sim/physics/trajectory_controller.hpp"

namespace ari_social_sim::physics {

/// ARI v1's joint trajectory controllers as PAL spawns them (ari_robot): head (goal tolerance
/// 0.5 rad, goal_time 2.0 s), arm_left/arm_right (joints 1-4, 0.02 rad, 0.6 s) and hand_left/
/// hand_right (the actuated fingers joint, 0.02 rad, 0.6 s); stopped_velocity_tolerance 5.0.
std::vector<ControllerSpec> ari_controller_specs();

/// A joint no controller commands that copies another (the hands' virtual finger joints follow
/// hand_{s}_fingers_joint with scale 1, as PAL's underactuated-finger Gazebo plugin does).
struct PassiveJoint {
  std::string joint;
  std::string follows;
};
std::vector<PassiveJoint> ari_passive_joints();

/// Joints AriPhysics sets itself instead of simulating their dynamics: the hands' three joints
/// (leaf links of 26 to 50 g whose servo would need a far smaller step than 1 ms; they follow
/// their saturated command exactly) and the casters (free wheels: their spin is the rolling of
/// the base over the floor). Neither changes a motion anyone measures, and leaving them out of
/// the multibody keeps it at 12 joints, which roughly halves the constraint solver's work per
/// step (docs/physics.md, "Speed").
std::vector<std::string> ari_kinematic_joints();

/// The drive wheels of mobile_base_controller (left, right) and the base frame of its odometry.
struct DriveJoints {
  std::string left_wheel{"wheel_left_joint"};
  std::string right_wheel{"wheel_right_joint"};
  std::string base_frame{"base_footprint"};
};

}  // namespace ari_social_sim::physics
