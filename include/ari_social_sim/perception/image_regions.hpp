#pragma once

#include <Eigen/Core>

#include "ari_social_sim/perception/field_of_view.hpp"
#include "ari_social_sim/perception/perception_frame.hpp"

// Where a person appears in ARI's images, for the REP-required `roi` topics. Both cameras are
// taken level with a 4:3 image; a region is clipped to the image.

namespace ari_social_sim::perception {

/// A vertical cylinder (a body: `radius_m`, from the floor to `top_m`) in an equidistant fisheye
/// image (x = 0.5 - bearing / field of view) whose optical centre is at `camera_height_m`.
ImageRegion fisheye_region(const FieldOfView& camera, double camera_height_m,
                           const Eigen::Vector2d& centre_map, double radius_m, double top_m);

/// A face (`width_m` x `height_m`, centred at `centre_height_m`) in a pinhole image.
ImageRegion pinhole_region(const FieldOfView& camera, double camera_height_m,
                           const Eigen::Vector2d& centre_map, double centre_height_m,
                           double width_m, double height_m);

}  // namespace ari_social_sim::perception
