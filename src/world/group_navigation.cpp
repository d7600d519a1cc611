#include "ari_social_sim/world/group_navigation.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/core/check.hpp"
#include "ari_social_sim/core/config_check.hpp"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/number_text.hpp"
#include "ari_social_sim/world/human.hpp"
#include "ari_social_sim/world/simulation.hpp"
#include "ari_social_sim/world/social_forces.hpp"
#include "ari_social_sim/world/step_motion.hpp"

namespace ari_social_sim::world {

bool GroupSpec::lists_a_member_twice() const {
  return std::set<model::ObjectId>(members.begin(), members.end()).size() != members.size();
}

void GroupSpec::validate() const {
  core::check_fields<core::RequestError>(*this, "");
}

GroupNavigation::GroupNavigation(const GroupSpec& spec) : spec_(spec) {}

double GroupNavigation::ospace_radius_for(size_t member_count, double spacing_m,
                                          double min_radius_m) {
  if (member_count < 2) {
    return min_radius_m;
  }
  const double radius = spacing_m / (2.0 * std::sin(core::kPi / static_cast<double>(member_count)));
  return std::max(min_radius_m, radius);
}

double GroupNavigation::ospace_radius_m() const {
  return spec_.ospace_radius_m > 0.0
             ? spec_.ospace_radius_m
             : ospace_radius_for(spec_.members.size(), spec_.member_spacing_m,
                                 spec_.min_ospace_radius_m);
}

double GroupNavigation::member_personal_distance_m() const {
  const size_t n = spec_.members.size();
  if (n < 2) {
    return 0.0;
  }
  return spec_.spacing_factor * 2.0 * ospace_radius_m() *
         std::sin(core::kPi / static_cast<double>(n));
}

double GroupNavigation::cohesion_radius_m() const {
  const size_t n = spec_.members.size();
  const double s = ospace_radius_m();
  if (n < 2) {
    return s;
  }
  // With evenly spaced members the repulsion of the two neighbours pushes each member outward by
  // (Delta_p - chord)^2; cohesion toward s minus that amount balances it exactly on the circle s.
  const double chord = 2.0 * s * std::sin(core::kPi / static_cast<double>(n));
  const double excess = std::max(0.0, member_personal_distance_m() - chord);
  return std::max(0.0, s - excess * excess);
}

void GroupNavigation::set_centre(const Eigen::Vector2d& centre) {
  ARI_DCHECK(centre.allFinite());
  spec_.centre = centre;
}

void GroupNavigation::remove_member(model::ObjectId id) {
  spec_.members.erase(std::remove(spec_.members.begin(), spec_.members.end(), id),
                      spec_.members.end());
}

void GroupNavigation::step(const StepContext& context) {
  Simulation& simulation = context.simulation;
  member_positions_.clear();
  for (model::ObjectId id : spec_.members) {
    member_positions_.push_back(simulation.find_human(id)->pose().position);
  }
  const double member_personal_distance = member_personal_distance_m();
  const int group_size = static_cast<int>(spec_.members.size());
  const double cohesion_radius = cohesion_radius_m();

  for (size_t i = 0; i < spec_.members.size(); ++i) {
    Human& human = *simulation.mutable_human(spec_.members[i]);
    const HumanMotionParams& params = human.spec().motion;
    const Eigen::Vector2d& p = member_positions_[i];

    // Members inside the social space (eq. 3.13), and all other members (eq. 3.18).
    social_neighbours_.clear();
    others_.clear();
    for (size_t j = 0; j < member_positions_.size(); ++j) {
      if (j == i) {
        continue;
      }
      others_.push_back(member_positions_[j]);
      if ((member_positions_[j] - p).norm() < spec_.social_distance_m) {
        social_neighbours_.push_back(member_positions_[j]);
      }
    }
    // Agents outside the group keep the member's own personal distance.
    simulation.agent_centres_near(p, params.personal_distance_m, &human, outsiders_, spec_.id);

    // Eq. 3.9: repulsion (members at the group's spacing, others at the personal distance),
    // equality and cohesion.
    const Eigen::Vector2d force =
        social_forces::repulsion_force(p, others_, member_personal_distance) +
        social_forces::repulsion_force(p, outsiders_, params.personal_distance_m) +
        social_forces::equality_force(p, social_neighbours_) +
        social_forces::cohesion_force(p, spec_.centre, cohesion_radius, group_size,
                                      static_cast<int>(social_neighbours_.size()));
    // Eq. 3.10: the orientation vectors are summed and the member turns toward their direction.
    const Eigen::Vector2d facing = social_forces::equality_orientation(p, social_neighbours_) +
                                   social_forces::cohesion_orientation(p, others_);
    double turn = 0.0;
    if (facing.squaredNorm() > 1e-12) {
      turn = core::angle_difference(std::atan2(facing.y(), facing.x()), human.pose().theta);
    } else if ((spec_.centre - p).squaredNorm() > 1e-12) {
      // A lone member faces the o-space centre.
      const Eigen::Vector2d to_centre = spec_.centre - p;
      turn = core::angle_difference(std::atan2(to_centre.y(), to_centre.x()), human.pose().theta);
    }
    // Eq. 3.11-3.12.
    HumanMotionParams group_params = params;
    group_params.walking_speed_mps = spec_.step_speed_mps;
    human.plan_motion(step_motion(force, group_params).velocity_mps,
                      rotation_step(turn, params, context.dt_s));
  }
}

}  // namespace ari_social_sim::world
