#include "ari_social_sim/physics/ari_controllers.hpp"

namespace ari_social_sim::physics {

std::vector<ControllerSpec> ari_controller_specs() {
  std::vector<ControllerSpec> specs;
  specs.push_back({"head_controller", {"head_1_joint", "head_2_joint"}, 0.5, 2.0, 5.0});
  for (const std::string side : {"left", "right"}) {
    const std::string arm = "arm_" + side;
    specs.push_back({arm + "_controller",
                     {arm + "_1_joint", arm + "_2_joint", arm + "_3_joint", arm + "_4_joint"},
                     0.02,
                     0.6,
                     5.0});
    specs.push_back(
        {"hand_" + side + "_controller", {"hand_" + side + "_fingers_joint"}, 0.02, 0.6, 5.0});
  }
  return specs;
}

std::vector<PassiveJoint> ari_passive_joints() {
  std::vector<PassiveJoint> joints;
  for (const std::string side : {"left", "right"}) {
    const std::string hand = "hand_" + side;
    joints.push_back({hand + "_virtual_1_joint", hand + "_fingers_joint"});
    joints.push_back({hand + "_virtual_2_joint", hand + "_fingers_joint"});
  }
  return joints;
}

std::vector<std::string> ari_kinematic_joints() {
  std::vector<std::string> joints;
  for (const std::string side : {"left", "right"}) {
    joints.push_back("hand_" + side + "_fingers_joint");
    joints.push_back("hand_" + side + "_virtual_1_joint");
    joints.push_back("hand_" + side + "_virtual_2_joint");
    joints.push_back("caster_" + side + "_joint");
  }
  return joints;
}

}  // namespace ari_social_sim::physics
