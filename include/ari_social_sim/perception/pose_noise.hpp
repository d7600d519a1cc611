#pragma once

#include "ari_social_sim/core/pose2.hpp"
#include "ari_social_sim/core/rng.hpp"
#include "ari_social_sim/perception/perception_config.hpp"

namespace ari_social_sim::perception {

/// `truth` with independent Gaussian noise on x, y (stddev PoseNoise::position_stddev_m) and
/// theta (orientation_stddev_deg), both at `distance_m` from the sensor. Noise-free settings
/// return `truth` unchanged and draw nothing.
core::Pose2 perturb_pose(const PoseNoise& noise, const core::Pose2& truth, double distance_m,
                         core::Rng& rng);

}  // namespace ari_social_sim::perception
