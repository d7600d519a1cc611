#pragma once

#include <vector>

#include "ari_social_sim/physics/robot_model.hpp"
#include "ari_social_sim/rendering/render_primitive.hpp"
#include "ari_social_sim/rendering/world_scene.hpp"

namespace ari_social_sim::rendering {

/// ARI's own body as the cameras see it: one primitive per visual shape of every link, placed by
/// the link's pose (`X_world_links` indexed like model.links(), e.g. AriPhysics::link_poses()),
/// in the URDF material's colour. Shapes under 3 mm across (PAL's dummy finger sphere) are left
/// out.
std::vector<RenderPrimitive> robot_primitives(const physics::RobotModel& model,
                                              const std::vector<Eigen::Isometry3d>& X_world_links);

}  // namespace ari_social_sim::rendering
