#pragma once

#include <cctype>
#include <string>

namespace ari_social_sim::nodes {

/// True if `id` can be a ROS4HRI id: a name segment of its per-id topics and tf frames
/// (/humans/persons/<id>/body_id, person_<id>), i.e. a letter then letters, digits or
/// underscores. roscpp aborts the node (ros::InvalidNameException) when asked to subscribe to a
/// topic built from anything else, so ids received from other nodes are checked first.
inline bool is_valid_hri_id(const std::string& id) {
  if (id.empty() || !std::isalpha(static_cast<unsigned char>(id.front()))) {
    return false;
  }
  for (const char c : id) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') {
      return false;
    }
  }
  return true;
}

}  // namespace ari_social_sim::nodes
