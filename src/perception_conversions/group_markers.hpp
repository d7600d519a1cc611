#pragma once

#include <visualization_msgs/MarkerArray.h>

#include <string>
#include <vector>

#include "ari_social_sim/perception/group_perception.hpp"

namespace ari_social_sim::nodes {

/// The groups group detection found, in one MarkerArray in `frame_id` (the frame of the groups'
/// centres): each group's o-space centre as a small cyan circle with its group id, drawn to sit
/// beside the world's ground-truth o-space circles. Starts with DELETEALL, so groups gone since
/// the last array disappear.
visualization_msgs::MarkerArray group_markers(const std::vector<perception::PerceivedGroup>& groups,
                                              const std::string& frame_id);

}  // namespace ari_social_sim::nodes
