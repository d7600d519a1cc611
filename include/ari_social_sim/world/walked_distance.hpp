#pragma once

#include <Eigen/Core>

// How far a human has walked on foot, the cameras' gait phase (HumanSnapshot::walked_m). The world
// counts it step by step; the physics and hri_perception_node walk a report of it on to the
// instant they draw or pose the person. All three go on by this one rule, so that every figure
// of a person posed from the same state takes the same stride.

namespace ari_social_sim::world {

/// `walked_m` walked on for `dt_s` at `velocity_mps`; unchanged while the human is seated or
/// changing posture (`seated_fraction` above 0): standing up and sitting down take no stride.
inline double walked_on(double walked_m, const Eigen::Vector2d& velocity_mps,
                        double seated_fraction, double dt_s) {
  return seated_fraction == 0.0 ? walked_m + velocity_mps.norm() * dt_s : walked_m;
}

}  // namespace ari_social_sim::world
