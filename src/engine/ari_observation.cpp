#include "ari_social_sim/engine/ari_observation.hpp"

namespace ari_social_sim::engine {

navigation::RobotObservation observe_ari(const world::Ari& ari) {
  navigation::RobotObservation robot;
  robot.pose = ari.pose();
  robot.linear_mps = ari.drive().linear_mps();
  robot.angular_rps = ari.drive().angular_rps();
  robot.pan_rad = ari.head().pan_rad();
  robot.pan_rps = ari.head().pan_velocity_rps();
  return robot;
}

}  // namespace ari_social_sim::engine
