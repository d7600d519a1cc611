#include "input_counters.hpp"

#include <diagnostic_msgs/DiagnosticArray.h>
#include <ros/console.h>

#include <cmath>

#include "ari_social_sim/core/number_text.hpp"
#include "ari_social_sim/model/tracked_person.hpp"

namespace ari_social_sim::nodes {
namespace {

constexpr double kStatusPeriodS = 1.0;
constexpr double kDropWarningPeriodS = 5.0;

diagnostic_msgs::KeyValue key_value(const std::string& key, uint64_t value) {
  diagnostic_msgs::KeyValue pair;
  pair.key = key;
  pair.value = std::to_string(value);
  return pair;
}

}  // namespace

bool InputCounters::finite(const std::string& topic, const std::string& field, double value) {
  if (std::isfinite(value)) {
    return true;
  }
  drop(topic, field, core::number_text(value) + ", not a finite number");
  return false;
}

bool InputCounters::plausible(const std::string& transform, const core::Pose2& pose) {
  const std::string problem = model::pose_problem(pose);
  if (problem.empty()) {
    return true;
  }
  drop("tf", transform, problem);
  return false;
}

void InputCounters::drop(const std::string& topic, const std::string& field,
                         const std::string& what) {
  Count& count = drops_[topic + " " + field];
  ++count.dropped;
  const ros::WallTime now = ros::WallTime::now();
  if (count.dropped == 1 || (now - count.last_warning).toSec() >= kDropWarningPeriodS) {
    count.last_warning = now;
    ROS_WARN("%s: dropped a message whose %s is %s (%lu dropped for it)", topic.c_str(),
             field.c_str(), what.c_str(), static_cast<unsigned long>(count.dropped));
  }
}

void InputCounters::publish_when_due(ros::Publisher& diagnostics, const ros::Time& stamp) {
  const ros::WallTime now = ros::WallTime::now();
  if ((now - last_status_).toSec() < kStatusPeriodS) {
    return;
  }
  last_status_ = now;
  diagnostic_msgs::DiagnosticArray array;
  array.header.stamp = stamp;
  array.status.push_back(status());
  diagnostics.publish(array);
}

diagnostic_msgs::DiagnosticStatus InputCounters::status() const {
  diagnostic_msgs::DiagnosticStatus status;
  status.name = node_ + ": inputs";
  status.hardware_id = "ari_social_sim";
  uint64_t dropped = 0;
  for (const auto& [key, count] : drops_) {
    dropped += count.dropped;
    status.values.push_back(key_value("dropped " + key, count.dropped));
  }
  for (const auto& [topic, clamped] : clamps_) {
    status.values.push_back(key_value("clamped " + topic, clamped));
  }
  status.level =
      dropped > 0 ? diagnostic_msgs::DiagnosticStatus::WARN : diagnostic_msgs::DiagnosticStatus::OK;
  status.message =
      dropped > 0 ? std::to_string(dropped) + " input messages dropped" : "no input dropped";
  return status;
}

}  // namespace ari_social_sim::nodes
