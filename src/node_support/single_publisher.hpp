#pragma once

#include <ros/time.h>

#include <string>

#include "input_counters.hpp"

namespace ari_social_sim::nodes {

/// Keeps a topic that one node alone should publish (/map, /sim/world_state: world_node's) to the
/// first node heard on it. A second world_node started by mistake publishes its own map and
/// world: mixed in, perception and navigation would follow it for good. Its messages are refused,
/// counted as drops on `inputs` (if given) and reported with ROS_ERROR (throttled) naming both
/// publishers; once the first publisher no longer publishes the topic (the master says so), the
/// next one heard takes over. Callers pass the message's publisher
/// (ros::MessageEvent::getPublisherName, the connection header's callerid).
class SinglePublisher {
 public:
  explicit SinglePublisher(const std::string& topic, InputCounters* inputs = nullptr);

  /// True if a message `publisher` sent on the topic is to be used.
  bool accept(const std::string& publisher);
  /// The publisher messages are taken from; "" before the first.
  const std::string& owner() const { return owner_; }

 private:
  /// Whether the master lists `node` among the topic's publishers; asked at most once per
  /// kMasterQueryPeriod_s of wall time (the answer is kept in between), so that a flood from the
  /// second publisher cannot flood the master.
  bool still_publishing(const std::string& node);

  static constexpr double kMasterQueryPeriod_s = 1.0;
  static constexpr double kErrorPeriod_s = 5.0;  // wall seconds between errors

  std::string topic_;
  InputCounters* inputs_;
  std::string owner_;
  bool owner_publishing_{true};
  ros::WallTime last_query_;
  ros::WallTime last_error_;
};

/// Reports (ROS_ERROR naming them all) when the master lists more than one publisher of a topic
/// whose messages a node cannot refuse by publisher: /clock, which roscpp subscribes to itself. A
/// second world_node's clock still mixes in; this says so, loudly.
class PublisherCountWatch {
 public:
  explicit PublisherCountWatch(const std::string& topic);

  /// Asks the master at most once per kPeriod_s of wall time; call it from a timer or callback.
  void check_when_due();

 private:
  static constexpr double kPeriod_s = 1.0;
  static constexpr double kErrorPeriod_s = 5.0;

  std::string topic_;
  ros::WallTime last_check_;
  ros::WallTime last_error_;
};

}  // namespace ari_social_sim::nodes
