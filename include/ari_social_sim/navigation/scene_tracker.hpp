#pragma once

#include <Eigen/Core>
#include <map>
#include <string>
#include <vector>

#include "ari_social_sim/core/yaml_map.hpp"
#include "ari_social_sim/navigation/perceived_scene.hpp"

namespace ari_social_sim::navigation {

/// How perception reports become a PerceivedScene (social_mpc_node).
struct SceneTrackerConfig {
  double velocity_time_constant_s{0.5};  // smoothing of velocities estimated from positions
  double person_timeout_s{1.0};          // a person not reported for this long is dropped
  double group_timeout_s{1.0};           // a group not reported for this long is dropped
  double group_stride_m{0.5};            // GCFF stride that places a group's o-space centre

  void read(const core::YamlMap& map);
};

/// Keeps what perception last said about each person and group: poses with velocities estimated
/// by smoothed finite differences (ROS4HRI carries no person velocity), group memberships, and
/// turns them into the scene the navigator plans with. Ids are ROS4HRI person and group ids.
class SceneTracker {
 public:
  explicit SceneTracker(const SceneTrackerConfig& config) : config_(config) {}

  /// A person seen at `time_s` (map frame).
  void observe_person(const std::string& id, double time_s, const Eigen::Vector2d& position,
                      double heading);
  /// A group reported at `time_s` with these person ids (non-person ids are ignored later).
  void observe_group(const std::string& id, double time_s, const std::vector<std::string>& members);
  /// People reported within the person timeout and groups within the group timeout that have at
  /// least two known members, each with its o-space from the members' poses.
  PerceivedScene scene(double time_s) const;
  void clear();

 private:
  struct Track {
    PersonEstimate estimate;
    double time_s{0.0};
    bool has_velocity{false};
  };
  struct GroupReport {
    std::vector<std::string> members;
    double time_s{0.0};
  };
  SceneTrackerConfig config_;
  std::map<std::string, Track> people_;
  std::map<std::string, GroupReport> groups_;
};

}  // namespace ari_social_sim::navigation
