#pragma once

#include <visualization_msgs/MarkerArray.h>

#include "ari_social_sim/perception/perception_config.hpp"
#include "ari_social_sim/perception/perception_frame.hpp"

namespace ari_social_sim::nodes {

/// What ARI perceives in one MarkerArray, in `frame_id` (the map), drawn to sit beside the
/// world's ground-truth markers: the fisheye's and the head camera's fields of view and the
/// microphones' range (translucent), each tracked body (blue cylinder, heading, "body id /
/// person"), each face (sellion sphere, gaze arrow, "face id: age, gender, expression, mask"),
/// each voice with what the recogniser has heard, and persons no longer tracked fading with their
/// location confidence (groups are group_detection_node's: group_markers). Starts with DELETEALL.
visualization_msgs::MarkerArray perception_markers(const perception::PerceptionFrame& frame,
                                                   const perception::PerceptionConfig& config,
                                                   const std::string& frame_id);

}  // namespace ari_social_sim::nodes
