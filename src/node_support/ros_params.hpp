#pragma once

#include <ros/node_handle.h>

#include "ari_social_sim/core/yaml_map.hpp"

namespace ari_social_sim::nodes {

/// All of a node's private parameters as one strict mapping, so the cores' loaders (which name
/// bad fields and reject unknown ones) read the parameter server exactly as they read files.
/// Messages name the source as "<node> parameter" (e.g. `/world_node parameter: step: ...`).
core::YamlMap read_private_params(const ros::NodeHandle& private_handle);

}  // namespace ari_social_sim::nodes
