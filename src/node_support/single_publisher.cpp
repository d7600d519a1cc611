#include "single_publisher.hpp"

#include <ros/console.h>
#include <ros/master.h>
#include <ros/names.h>
#include <ros/this_node.h>
#include <xmlrpcpp/XmlRpcValue.h>

#include <algorithm>
#include <optional>
#include <vector>

namespace ari_social_sim::nodes {
namespace {

// The publishers of `topic` as the master lists them (getSystemState), or nothing when the
// master cannot be asked.
std::optional<std::vector<std::string>> publishers_of(const std::string& topic) {
  XmlRpc::XmlRpcValue args, result, payload;
  args[0] = ros::this_node::getName();
  if (!ros::master::execute("getSystemState", args, result, payload, false)) {
    return std::nullopt;
  }
  std::vector<std::string> nodes;
  XmlRpc::XmlRpcValue& publications = payload[0];
  // Not a range-for: XmlRpcValue's begin() walks a struct's members, not an array's items.
  // NOLINTNEXTLINE(modernize-loop-convert)
  for (int i = 0; i < publications.size(); ++i) {
    if (static_cast<std::string>(publications[i][0]) != topic) {
      continue;
    }
    for (int j = 0; j < publications[i][1].size(); ++j) {
      nodes.push_back(static_cast<std::string>(publications[i][1][j]));
    }
  }
  return nodes;
}

}  // namespace

SinglePublisher::SinglePublisher(const std::string& topic, InputCounters* inputs)
    : topic_(ros::names::resolve(topic)), inputs_(inputs) {
  if (inputs_) {
    inputs_->declare_drop(topic_, "publisher");
  }
}

bool SinglePublisher::still_publishing(const std::string& node) {
  const ros::WallTime now = ros::WallTime::now();
  if ((now - last_query_).toSec() < kMasterQueryPeriod_s) {
    return owner_publishing_;
  }
  last_query_ = now;
  const std::optional<std::vector<std::string>> nodes = publishers_of(topic_);
  // A master that cannot answer is no proof the first publisher left: keep it.
  owner_publishing_ = !nodes || std::find(nodes->begin(), nodes->end(), node) != nodes->end();
  return owner_publishing_;
}

bool SinglePublisher::accept(const std::string& publisher) {
  if (owner_.empty() || publisher == owner_) {
    owner_ = publisher;
    return true;
  }
  if (!still_publishing(owner_)) {
    ROS_WARN("%s: its publisher %s has gone; taking it from %s from now on", topic_.c_str(),
             owner_.c_str(), publisher.c_str());
    owner_ = publisher;
    owner_publishing_ = true;
    return true;
  }
  // Throttled per topic (ROS_ERROR_THROTTLE would share one throttle between all topics).
  const ros::WallTime now = ros::WallTime::now();
  if (last_error_.isZero() || (now - last_error_).toSec() >= kErrorPeriod_s) {
    last_error_ = now;
    ROS_ERROR(
        "%s: a second publisher, %s, besides %s (a second world_node?): its messages are "
        "refused while %s publishes",
        topic_.c_str(), publisher.c_str(), owner_.c_str(), owner_.c_str());
  }
  if (inputs_) {
    inputs_->drop(topic_, "publisher", publisher + ", expected " + owner_ + " alone");
  }
  return false;
}

PublisherCountWatch::PublisherCountWatch(const std::string& topic)
    : topic_(ros::names::resolve(topic)) {}

void PublisherCountWatch::check_when_due() {
  const ros::WallTime now = ros::WallTime::now();
  if ((now - last_check_).toSec() < kPeriod_s) {
    return;
  }
  last_check_ = now;
  const std::optional<std::vector<std::string>> nodes = publishers_of(topic_);
  if (!nodes || nodes->size() < 2 ||
      (!last_error_.isZero() && (now - last_error_).toSec() < kErrorPeriod_s)) {
    return;
  }
  last_error_ = now;
  std::string names;
  for (const std::string& node : *nodes) {
    names += (names.empty() ? "" : ", ") + node;
  }
  ROS_ERROR("%s: %zu publishers, %s (a second world_node?): their messages mix", topic_.c_str(),
            nodes->size(), names.c_str());
}

}  // namespace ari_social_sim::nodes
