#pragma once

#include <diagnostic_msgs/DiagnosticStatus.h>
#include <ros/publisher.h>
#include <ros/time.h>

#include <cstdint>
#include <map>
#include <string>

#include "ari_social_sim/core/pose2.hpp"

namespace ari_social_sim::nodes {

/// Subscriber queue of the small command and state topics whose messages a node checks. roscpp
/// drops the oldest message of a full queue without telling anyone, so with a queue of 1 a flood
/// of bad commands reached the checks (and the counters) once a spin: 160 of 6,054 at 1 kHz.
/// With room for a second of a 1 kHz flood between two spins, every message is checked and
/// counted; the callbacks apply each valid one in order, so the latest still wins.
constexpr uint32_t kCheckedInputQueue = 1000;

/// What a node did with the numbers of its input topics: messages dropped because a field it uses
/// is not finite (or the message does not make sense), and finite commands clamped to ARI's
/// limits, counted per topic and field, each drop warned about at most every
/// kDropWarningPeriodS per field, and reported as one DiagnosticStatus for /diagnostics.
class InputCounters {
 public:
  /// `node` names the status ("world_node: inputs").
  explicit InputCounters(std::string node) : node_(std::move(node)) {}

  /// Lists a counter (at 0) so that /diagnostics shows it before anything happens.
  void declare_drop(const std::string& topic, const std::string& field) {
    drops_.emplace(topic + " " + field, Count{});
  }
  void declare_clamp(const std::string& topic) { clamps_.emplace(topic, 0); }

  /// True if `value` is finite. Otherwise counts a drop of `topic`'s message for `field` and warns.
  bool finite(const std::string& topic, const std::string& field, double value);
  /// True if `pose` is a place in the map (model::pose_problem: finite, within
  /// model::kMaxMapCoordinateM). Otherwise counts a drop of the transform `transform` ("map ->
  /// base_footprint") under "tf" and warns, with the coordinates in %g form.
  bool plausible(const std::string& transform, const core::Pose2& pose);
  /// Counts a drop of `topic`'s message for `field` (which holds `what`) and warns.
  void drop(const std::string& topic, const std::string& field, const std::string& what);
  /// Counts `n` drops someone else warned about (RenewingTfBuffer's refused transforms).
  void add_drops(const std::string& topic, const std::string& field, uint64_t n) {
    drops_[topic + " " + field].dropped += n;
  }
  void add_clamps(const std::string& topic, uint64_t clamped) { clamps_[topic] += clamped; }

  /// Publishes the status on `diagnostics` (a diagnostic_msgs/DiagnosticArray publisher) stamped
  /// `stamp`, once a wall second at most (the diagnostics convention, 1 Hz).
  void publish_when_due(ros::Publisher& diagnostics, const ros::Time& stamp);
  diagnostic_msgs::DiagnosticStatus status() const;

 private:
  struct Count {
    uint64_t dropped{0};
    ros::WallTime last_warning;
  };

  std::string node_;
  std::map<std::string, Count> drops_;
  std::map<std::string, uint64_t> clamps_;
  ros::WallTime last_status_;
};

}  // namespace ari_social_sim::nodes
