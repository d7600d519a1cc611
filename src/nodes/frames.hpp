#pragma once

namespace ari_social_sim::nodes {

// The frames every node names (specs/ari.md §4): the map, the odometry frame and ARI's base.
inline constexpr char kMapFrame[] = "map";
inline constexpr char kOdomFrame[] = "odom";
inline constexpr char kBaseFrame[] = "base_footprint";

}  // namespace ari_social_sim::nodes
