#include "renewing_tf_buffer.hpp"

#include <string>
#include <vector>

namespace ari_social_sim::nodes {

RenewingTfBuffer::RenewingTfBuffer() : current_(std::make_unique<Listening>()) {}

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
    next_ = std::make_unique<Listening>();
    next_started_ = now;
  }
}

}  // namespace ari_social_sim::nodes
