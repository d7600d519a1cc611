#pragma once

#include <ros/callback_queue.h>
#include <ros/node_handle.h>
#include <ros/spinner.h>
#include <ros/subscriber.h>
#include <ros/time.h>
#include <tf2_msgs/TFMessage.h>
#include <tf2_ros/buffer.h>

#include <cstdint>
#include <memory>
#include <mutex>
#include <string>

namespace ari_social_sim::nodes {

/// A tf buffer and its listener that start afresh when the buffer holds many more frames than
/// are in use. tf2 keeps every frame it has ever seen, with its last seconds of transforms, and
/// has no way to forget one: in a node that looks up people's frames (body_<id>, person_<id>),
/// which come and go with the ids perception gives, memory would follow everyone ever seen.
/// A fresh listener gets the static transforms again (latched on /tf_static) and the moving ones
/// with their next message; it fills for a couple of seconds beside the old one, which answers
/// lookups until then. Lookups and renew_if_stale() belong to one thread (the node's spinner).
///
/// The listener (in place of tf2_ros::TransformListener) refuses absurd transforms
/// (model::transform_problem: inf, 1e300): tf2 would keep them, and a rogue map -> odom on /tf
/// would overwrite the static one for good. Like tf2_ros's, it runs on its own thread and clears
/// the buffer when sim time goes back (/sim/reset).
class RenewingTfBuffer {
 public:
  /// Transforms refused since the last take_refused(), and what was wrong with the last one.
  struct Refused {
    uint64_t count{0};
    std::string last;  // "map -> odom: translation x = 1e+300, ..."
  };

  RenewingTfBuffer();
  ~RenewingTfBuffer();
  RenewingTfBuffer(const RenewingTfBuffer&) = delete;
  RenewingTfBuffer& operator=(const RenewingTfBuffer&) = delete;

  /// The buffer to look transforms up in; replaced by renew_if_stale().
  const tf2_ros::Buffer& buffer() const;

  /// Call regularly (the node's timer): counts the frames at most once a wall second, starts a
  /// fresh listener when there are more than twice as many as after the last start plus
  /// kSpareFrames, and makes it current once it has listened for kFillTime_s.
  void renew_if_stale();

  /// The refused transforms counted since the last call (for a node's InputCounters), and resets
  /// the count. Without a caller, each refusal is still warned about (throttled).
  Refused take_refused();

 private:
  class Listening;
  static constexpr size_t kSpareFrames = 200;
  static constexpr double kFillTime_s = 2.0;

  static size_t frame_count(const tf2_ros::Buffer& buffer);
  /// Counts and warns about a refused transform (from a listener's thread).
  void refuse(const std::string& what);

  std::mutex refused_mutex_;  // the listeners' threads count, the node's thread takes
  Refused refused_;
  std::unique_ptr<Listening> current_;
  std::unique_ptr<Listening> next_;  // filling, while current_ answers
  ros::WallTime next_started_;
  ros::WallTime last_count_;
  size_t frames_after_start_{0};
};

}  // namespace ari_social_sim::nodes
