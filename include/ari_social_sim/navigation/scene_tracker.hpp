#pragma once

#include <Eigen/Core>
#include <map>
#include <string>
#include <vector>

#include "ari_social_sim/core/config_fields.hpp"
#include "ari_social_sim/navigation/perceived_scene.hpp"

namespace ari_social_sim::navigation {

/// How perception reports become a PerceivedScene (social_mpc_node).
struct SceneTrackerConfig {
  double position_noise_m{0.1};
  double acceleration_noise_mps2{1.0};
  double heading_time_constant_s{0.3};
  double person_timeout_s{2.0};
  double group_timeout_s{2.0};
  double group_stride_m{0.5};

  template <class V>
  void visit(V& v) {
    v.field("position_noise", position_noise_m,
            "m, standard deviation of a reported position (perception's noise)", core::positive());
    v.field("acceleration_noise", acceleration_noise_mps2,
            "m/s^2, how fast people change velocity (the filter's process noise)",
            core::positive());
    v.field("heading_time_constant", heading_time_constant_s, "s, smoothing of reported headings",
            core::positive());
    v.field("person_timeout", person_timeout_s,
            "s a person not reported (hidden, out of view) is kept", core::positive());
    v.field("group_timeout", group_timeout_s, "s a group, or a member of it, not reported is kept",
            core::positive());
    v.field("group_stride", group_stride_m, "m, GCFF stride that places a group's o-space centre",
            core::between(0.0, 2.0));
  }
};

/// Keeps what perception last said about each person and group, and turns it into the scene the
/// navigator plans with. ROS4HRI reports noisy positions and no velocities, so each person runs a
/// constant-velocity Kalman filter per axis (white-noise acceleration), which estimates their
/// velocity and steadies their position; headings are smoothed on the unit circle. A group keeps
/// a member for the group timeout after perception last listed it, so a member missed for a frame
/// does not reshape the group (and move the gap ARI is heading for). Ids are ROS4HRI ids.
class SceneTracker {
 public:
  /// A report or a call this much (s) earlier than what the tracker holds means that time went
  /// back (a world reset, a bag looping), not that a stamp lagged: what was held is from before.
  static constexpr double kTimeWentBack_s = 1.0;

  explicit SceneTracker(const SceneTrackerConfig& config) : config_(config) {}

  /// A person seen at `time_s` (map frame). A non-finite time or an absurd pose
  /// (model::pose_problem) is ignored; a report from before the person's track by more than
  /// kTimeWentBack_s starts the track afresh.
  void observe_person(const std::string& id, double time_s, const Eigen::Vector2d& position,
                      double heading);
  /// A group reported at `time_s` with these person ids (non-person ids are ignored later).
  void observe_group(const std::string& id, double time_s, const std::vector<std::string>& members);
  /// People reported within the person timeout, at their filtered state carried forward to
  /// `time_s` at their estimated velocity, and groups reported
  /// within the group timeout that have at least two known members, each with its o-space from
  /// the members' poses.
  PerceivedScene scene(double time_s) const;
  /// Drops what scene(`time_s`) would leave out: people not reported within the person timeout,
  /// groups and group members not within the group timeout. Call it once per control cycle, so
  /// that memory holds who is around, not everyone ever reported (ROS4HRI person and group ids
  /// come and go all run long). A person reported again after being dropped starts afresh
  /// (standing still, as a new person), rather than from a velocity estimate that old. People
  /// and groups last reported more than kTimeWentBack_s after `time_s` are dropped too.
  void forget(double time_s);
  void clear();

  /// People and groups held (for the soak benchmark).
  size_t person_count() const { return people_.size(); }
  size_t group_count() const { return groups_.size(); }

 private:
  struct Track {
    std::string id;
    double time_s{0.0};
    Eigen::Vector2d position{Eigen::Vector2d::Zero()};
    Eigen::Vector2d velocity{Eigen::Vector2d::Zero()};
    Eigen::Matrix2d covariance{Eigen::Matrix2d::Zero()};  // of (p, v), the same for x and y
    Eigen::Vector2d facing{1.0, 0.0};                     // smoothed unit heading
  };
  struct GroupReport {
    std::map<std::string, double> members;  // person id -> last time listed
    double time_s{0.0};
  };
  SceneTrackerConfig config_;
  std::map<std::string, Track> people_;
  std::map<std::string, GroupReport> groups_;
};

}  // namespace ari_social_sim::navigation
