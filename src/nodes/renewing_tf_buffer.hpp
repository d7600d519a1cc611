#pragma once

#include <ros/time.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include <memory>

namespace ari_social_sim::nodes {

/// A tf buffer and its listener that start afresh when the buffer holds many more frames than
/// are in use. tf2 keeps every frame it has ever seen, with its last seconds of transforms, and
/// has no way to forget one: in a node that looks up people's frames (body_<id>, person_<id>),
/// which come and go with the ids perception gives, memory would follow everyone ever seen.
/// A fresh listener gets the static transforms again (latched on /tf_static) and the moving ones
/// with their next message; it fills for a couple of seconds beside the old one, which answers
/// lookups until then. Lookups and renew_if_stale() belong to one thread (the node's spinner).
class RenewingTfBuffer {
 public:
  RenewingTfBuffer();
  RenewingTfBuffer(const RenewingTfBuffer&) = delete;
  RenewingTfBuffer& operator=(const RenewingTfBuffer&) = delete;

  /// The buffer to look transforms up in; replaced by renew_if_stale().
  const tf2_ros::Buffer& buffer() const { return current_->buffer; }

  /// Call regularly (the node's timer): counts the frames at most once a wall second, starts a
  /// fresh listener when there are more than twice as many as after the last start plus
  /// kSpareFrames, and makes it current once it has listened for kFillTime_s.
  void renew_if_stale();

 private:
  struct Listening {
    tf2_ros::Buffer buffer;
    tf2_ros::TransformListener listener{buffer};  // after buffer: stops before it goes
  };
  static constexpr size_t kSpareFrames = 200;
  static constexpr double kFillTime_s = 2.0;

  static size_t frame_count(const tf2_ros::Buffer& buffer);

  std::unique_ptr<Listening> current_;
  std::unique_ptr<Listening> next_;  // filling, while current_ answers
  ros::WallTime next_started_;
  ros::WallTime last_count_;
  size_t frames_after_start_{0};
};

}  // namespace ari_social_sim::nodes
