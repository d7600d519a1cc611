#include "renewing_tf_buffer.hpp"

#include <ros/console.h>
#include <ros/message_event.h>
#include <tf2/exceptions.h>

#include <vector>

#include "ari_social_sim/model/tracked_person.hpp"

namespace ari_social_sim::nodes {

/// One buffer with the subscriptions to /tf and /tf_static that fill it.
class RenewingTfBuffer::Listening {
 public:
  explicit Listening(RenewingTfBuffer& owner) : owner_(owner) {
    nh_.setCallbackQueue(&queue_);
    dynamic_ = nh_.subscribe("/tf", 100, &Listening::on_dynamic, this);
    static_ = nh_.subscribe("/tf_static", 100, &Listening::on_static, this);
    spinner_.start();
  }
  ~Listening() { spinner_.stop(); }  // no callback runs once the members go

  tf2_ros::Buffer buffer;

 private:
  void on_dynamic(const ros::MessageEvent<const tf2_msgs::TFMessage>& event) { take(event, false); }
  void on_static(const ros::MessageEvent<const tf2_msgs::TFMessage>& event) { take(event, true); }

  void take(const ros::MessageEvent<const tf2_msgs::TFMessage>& event, bool is_static) {
    // As tf2_ros::TransformListener: transforms from before a jump back would answer lookups.
    const ros::Time now = ros::Time::now();
    if (now < last_update_) {
      ROS_WARN("tf: sim time went back %.3f s; clearing the tf buffer",
               (last_update_ - now).toSec());
      buffer.clear();
    }
    last_update_ = now;
    clock_seen_ = clock_seen_ || !now.isZero();
    const std::string& authority = event.getPublisherName();
    for (const geometry_msgs::TransformStamped& t : event.getConstMessage()->transforms) {
      if (sent_before_a_reset(t, is_static, now)) {
        continue;
      }
      const geometry_msgs::Vector3& p = t.transform.translation;
      const geometry_msgs::Quaternion& q = t.transform.rotation;
      const std::string problem = model::transform_problem({p.x, p.y, p.z}, {q.x, q.y, q.z, q.w});
      if (!problem.empty()) {
        owner_.refuse(t.header.frame_id + " -> " + t.child_frame_id + " from " + authority + ": " +
                      problem);
        continue;
      }
      try {
        buffer.setTransform(t, authority, is_static);
      } catch (const tf2::TransformException& e) {
        ROS_WARN_THROTTLE(5.0, "tf: %s", e.what());
      }
    }
  }

  // A transform stamped more than tf2's cache time after the clock was sent before a reset and
  // delivered after it (a node still publishing the old timeline; the clock reads 0 right after a
  // reset). Stored, it would make tf2 refuse every transform after the reset as too old
  // (TF_OLD_DATA) until time caught up. Before any clock (the node starting) nothing is ahead.
  bool sent_before_a_reset(const geometry_msgs::TransformStamped& t, bool is_static,
                           const ros::Time& now) {
    if (is_static || !clock_seen_ || t.header.stamp <= now + buffer.getCacheLength()) {
      return false;
    }
    ROS_WARN_THROTTLE(5.0,
                      "tf: ignored %s -> %s stamped %.3f s, %.3f s after the clock (sent "
                      "before a reset?)",
                      t.header.frame_id.c_str(), t.child_frame_id.c_str(), t.header.stamp.toSec(),
                      (t.header.stamp - now).toSec());
    return true;
  }

  RenewingTfBuffer& owner_;
  ros::CallbackQueue queue_;
  ros::NodeHandle nh_;
  ros::Subscriber dynamic_, static_;
  ros::AsyncSpinner spinner_{1, &queue_};  // last: stops first
  ros::Time last_update_;
  bool clock_seen_{false};
};

RenewingTfBuffer::RenewingTfBuffer() : current_(std::make_unique<Listening>(*this)) {}

RenewingTfBuffer::~RenewingTfBuffer() = default;

const tf2_ros::Buffer& RenewingTfBuffer::buffer() const {
  return current_->buffer;
}

void RenewingTfBuffer::refuse(const std::string& what) {
  ROS_WARN_THROTTLE(5.0, "tf: refused %s", what.c_str());
  const std::lock_guard<std::mutex> lock(refused_mutex_);
  ++refused_.count;
  refused_.last = what;
}

RenewingTfBuffer::Refused RenewingTfBuffer::take_refused() {
  const std::lock_guard<std::mutex> lock(refused_mutex_);
  Refused taken = refused_;
  refused_.count = 0;
  return taken;
}

size_t RenewingTfBuffer::frame_count(const tf2_ros::Buffer& buffer) {
  std::vector<std::string> frames;
  buffer._getFrameStrings(frames);
  return frames.size();
}

void RenewingTfBuffer::renew_if_stale() {
  const ros::WallTime now = ros::WallTime::now();
  if (next_) {
    if ((now - next_started_).toSec() >= kFillTime_s) {
      current_ = std::move(next_);
      frames_after_start_ = frame_count(current_->buffer);
    }
    return;
  }
  if ((now - last_count_).toSec() < 1.0) {
    return;
  }
  last_count_ = now;
  if (frame_count(current_->buffer) > 2 * frames_after_start_ + kSpareFrames) {
    next_ = std::make_unique<Listening>(*this);
    next_started_ = now;
  }
}

}  // namespace ari_social_sim::nodes
