#include "ari_base.hpp"

#include "marker_builder.hpp"

namespace ari_social_sim::nodes {

geometry_msgs::TransformStamped map_to_odom(double stamp_s) {
  geometry_msgs::TransformStamped transform;
  transform.header.stamp = ros::Time(stamp_s);
  transform.header.frame_id = kMapFrame;
  transform.child_frame_id = kOdomFrame;
  transform.transform.rotation.w = 1.0;
  return transform;
}

geometry_msgs::TransformStamped odom_to_base(const world::AriSnapshot& ari, double stamp_s) {
  geometry_msgs::TransformStamped transform;
  transform.header.stamp = ros::Time(stamp_s);
  transform.header.frame_id = kOdomFrame;
  transform.child_frame_id = kBaseFrame;
  transform.transform.translation.x = ari.pose.position.x();
  transform.transform.translation.y = ari.pose.position.y();
  transform.transform.rotation = yaw_quaternion(ari.pose.theta);
  return transform;
}

nav_msgs::Odometry to_odometry(const world::AriSnapshot& ari, double stamp_s) {
  nav_msgs::Odometry odom;
  odom.header.stamp = ros::Time(stamp_s);
  odom.header.frame_id = kOdomFrame;
  odom.child_frame_id = kBaseFrame;
  odom.pose.pose.position.x = ari.pose.position.x();
  odom.pose.pose.position.y = ari.pose.position.y();
  odom.pose.pose.orientation = yaw_quaternion(ari.pose.theta);
  odom.twist.twist.linear.x = ari.linear_mps;
  odom.twist.twist.angular.z = ari.angular_rps;
  return odom;
}

}  // namespace ari_social_sim::nodes
