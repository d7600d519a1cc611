#include "group_markers.hpp"

#include "world_conversions/marker_builder.hpp"

namespace ari_social_sim::nodes {

visualization_msgs::MarkerArray group_markers(const std::vector<perception::PerceivedGroup>& groups,
                                              const std::string& frame_id) {
  visualization_msgs::MarkerArray array;
  MarkerBuilder b(frame_id, array);
  b.delete_all();
  int id = 0;
  for (const perception::PerceivedGroup& group : groups) {
    b.circle("perception/groups", id, group.centre.x(), group.centre.y(), 0.05, 0.35, 0.05,
             rgba(0.3f, 1.0f, 1.0f));
    b.text("perception/groups/label", id, group.centre.x(), group.centre.y(), 0.4,
           "group " + group.group_id, 0.22, rgba(0.0f, 0.4f, 0.45f));
    ++id;
  }
  return array;
}

}  // namespace ari_social_sim::nodes
