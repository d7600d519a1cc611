#pragma once

#include "ari_social_sim/navigation/navigator.hpp"
#include "ari_social_sim/world/ari.hpp"

namespace ari_social_sim::engine {

/// The simulated 2D ARI as the navigator measures it (odometry and head_1_joint), for loops that
/// run the world in-process: the batch tool and the navigation benchmark. Live, social_mpc_node
/// measures the same from /mobile_base_controller/odom and /joint_states.
navigation::RobotObservation observe_ari(const world::Ari& ari);

}  // namespace ari_social_sim::engine
