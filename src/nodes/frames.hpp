#pragma once

namespace ari_social_sim::nodes {

// The frames every node names (specs/ari.md §4): the map, the odometry frame and ARI's base.
inline constexpr char kMapFrame[] = "map";
inline constexpr char kOdomFrame[] = "odom";
inline constexpr char kBaseFrame[] = "base_footprint";
// ARI's head joints (pan, tilt), as its controllers and /joint_states name them.
inline constexpr char kHeadPanJoint[] = "head_1_joint";
inline constexpr char kHeadTiltJoint[] = "head_2_joint";

}  // namespace ari_social_sim::nodes
