#include "ari_social_sim/world/group_navigation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/core/check.hpp"
#include "ari_social_sim/core/config_check.hpp"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/core/number_text.hpp"
#include "ari_social_sim/core/rng.hpp"
#include "ari_social_sim/core/rng_streams.hpp"
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

GroupNavigation::GroupNavigation(const GroupSpec& spec)
    : spec_(spec), arranged_size_(spec.members.size()), heading_rad_(spec.heading_rad) {}

double GroupNavigation::ospace_radius_for(size_t member_count, double spacing_m,
                                          double min_radius_m) {
  if (member_count < 2) {
    return min_radius_m;
  }
  const double radius = spacing_m / (2.0 * std::sin(core::kPi / static_cast<double>(member_count)));
  return std::max(min_radius_m, radius);
}

size_t GroupNavigation::participant_count() const {
  return spec_.members.size() + (robot_joining_ != model::kNoObject ? 1 : 0);
}

bool GroupNavigation::kept_as_circle() const {
  // Someone joining rows turns them into a circle, so that the newcomer takes part: as D6.4
  // §3.4.2's L-shaped pair opens into a circle when a third person arrives.
  return spec_.arrangement == model::Arrangement::kCircle ||
         participant_count() > std::max<size_t>(arranged_size_, 2);
}

model::Arrangement GroupNavigation::arrangement() const {
  if (!kept_as_circle()) {
    return spec_.arrangement;
  }
  // Two around a circle face each other across it.
  return participant_count() == 2 ? model::Arrangement::kVisAVis : model::Arrangement::kCircle;
}

double GroupNavigation::formation_radius_for(const GroupSpec& spec, model::Arrangement arrangement,
                                             size_t participants) {
  if (spec.ospace_radius_m > 0.0) {
    return spec.ospace_radius_m;
  }
  if (arrangement == model::Arrangement::kCircle) {
    return ospace_radius_for(participants, spec.member_spacing_m, spec.min_ospace_radius_m);
  }
  return row_distance_for(arrangement, participants, spec.member_spacing_m,
                          spec.shoulder_spacing_m);
}

FormationShape GroupNavigation::settled_shape(const GroupSpec& spec, size_t participants) {
  FormationShape shape;
  shape.arrangement = spec.arrangement;
  shape.centre = spec.centre;
  shape.heading_rad = spec.heading_rad.value_or(0.0);
  shape.radius_m = formation_radius_for(spec, spec.arrangement, participants);
  shape.shoulder_spacing_m = spec.shoulder_spacing_m;
  return shape;
}

double GroupNavigation::ospace_radius_m() const {
  return formation_radius_for(spec_,
                              kept_as_circle() ? model::Arrangement::kCircle : spec_.arrangement,
                              participant_count());
}

double GroupNavigation::member_personal_distance_m() const {
  const size_t n = participant_count();
  if (n < 2) {
    return 0.0;
  }
  return spec_.spacing_factor * 2.0 * ospace_radius_m() *
         std::sin(core::kPi / static_cast<double>(n));
}

double GroupNavigation::cohesion_radius_m() const {
  const size_t n = participant_count();
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
  // The formation moves with its centre, each place by the same offset.
  for (FormationSlot& place : places_) {
    place.position += centre - spec_.centre;
  }
  spec_.centre = centre;
}

void GroupNavigation::add_member(model::ObjectId id) {
  spec_.members.push_back(id);
  formation_changed();
}

void GroupNavigation::remove_member(model::ObjectId id) {
  spec_.members.erase(std::remove(spec_.members.begin(), spec_.members.end(), id),
                      spec_.members.end());
  formation_changed();
}

void GroupNavigation::set_arrangement(model::Arrangement arrangement,
                                      std::optional<double> heading_rad) {
  ARI_DCHECK(!heading_rad || std::isfinite(*heading_rad));
  spec_.arrangement = arrangement;
  spec_.heading_rad = heading_rad;
  heading_rad_ = heading_rad;
  arranged_size_ = spec_.members.size();
  formation_changed();
}

void GroupNavigation::robot_join(model::ObjectId ari_id) {
  robot_asked_to_join_ = true;
  robot_asked_to_leave_ = false;
  if (robot_joining_ != ari_id) {
    robot_joining_ = ari_id;
    formation_changed();
  }
}

void GroupNavigation::robot_leave() {
  robot_asked_to_join_ = false;
  robot_asked_to_leave_ = true;
  if (robot_joining_ != model::kNoObject) {
    robot_joining_ = model::kNoObject;
    formation_changed();
  }
}

void GroupNavigation::update_robot_joining(const Simulation& simulation) {
  const Ari* ari = simulation.ari();
  model::ObjectId joining = model::kNoObject;
  if (ari != nullptr) {
    const Eigen::Vector2d to_centre = spec_.centre - ari->centre();
    const double beyond_radius = to_centre.norm() - ospace_radius_m();
    if (robot_asked_to_leave_ && beyond_radius > kRobotLeaveReachM) {
      robot_asked_to_leave_ = false;
    }
    const double facing_off = std::abs(
        core::angle_difference(std::atan2(to_centre.y(), to_centre.x()), ari->pose().theta));
    const bool approaching = beyond_radius < kRobotJoinReachM && facing_off < kRobotJoinFacingRad;
    const bool staying = robot_joining_ != model::kNoObject && beyond_radius < kRobotLeaveReachM;
    if (robot_asked_to_join_ || (!robot_asked_to_leave_ && (approaching || staying))) {
      joining = ari->id();
    }
  }
  if (joining != robot_joining_) {
    robot_joining_ = joining;
    formation_changed();
  }
}

void GroupNavigation::resolve_heading() {
  // The bearing of where the members stand: the first member for a circle, the members' mean
  // for rows (so that the rows form on the side they already are).
  Eigen::Vector2d towards = Eigen::Vector2d::Zero();
  const size_t used = kept_as_circle() ? 1 : spec_.members.size();
  for (size_t i = 0; i < used && i < participant_positions_.size(); ++i) {
    towards += participant_positions_[i] - spec_.centre;
  }
  heading_rad_ = towards.squaredNorm() > 1e-6 ? std::atan2(towards.y(), towards.x()) : 0.0;
}

void GroupNavigation::step(const StepContext& context) {
  Simulation& simulation = context.simulation;
  update_robot_joining(simulation);
  participant_positions_.clear();
  for (model::ObjectId id : spec_.members) {
    participant_positions_.push_back(simulation.find_human(id)->pose().position);
  }
  if (robot_joining_ != model::kNoObject) {
    participant_positions_.push_back(simulation.ari()->centre());
  }
  // Rows are laid out from a bearing; a formation that turns from a circle into rows again
  // takes it anew from where the members stand, unless the spec fixed it.
  const bool circle = kept_as_circle();
  if (!heading_rad_ || (!spec_.heading_rad && !circle && was_circle_)) {
    resolve_heading();
  }
  was_circle_ = circle;
  deal_places(circle);
  if (circle) {
    step_circle(context);
  } else {
    step_rows(context);
  }
}

void GroupNavigation::deal_places(bool circle) {
  const size_t n = participant_count();
  if (circle && spec_.place_gain <= 0.0) {
    places_.clear();
    slot_of_.clear();  // places are dealt afresh should the group stand in rows again
    return;
  }
  // While ARI comes to a circle, the gap follows it round: people make room where it comes.
  // Once ARI is at the ring the places stay, so that the place it aims at stops moving.
  const bool robot_coming =
      circle && robot_joining_ != model::kNoObject &&
      (participant_positions_.back() - spec_.centre).norm() > ospace_radius_m() + kRobotSettledM;
  const bool redeal = slots_stale_ || slot_of_.size() != n || robot_coming;
  if (!redeal) {
    return;  // the shape changes only with a redeal (set_centre moves the places it has)
  }
  if (circle) {
    // A circle opens its places toward its newest participant: ARI joining, or the member who
    // joined last.
    const Eigen::Vector2d towards = participant_positions_.back() - spec_.centre;
    if (towards.squaredNorm() > 1e-12) {
      circle_heading_rad_ = std::atan2(towards.y(), towards.x());
    }
  }
  FormationShape shape;
  shape.arrangement = circle ? model::Arrangement::kCircle : spec_.arrangement;
  shape.centre = spec_.centre;
  shape.heading_rad = circle ? circle_heading_rad_ : *heading_rad_;
  shape.radius_m = ospace_radius_m();
  shape.shoulder_spacing_m = spec_.shoulder_spacing_m;
  const std::vector<FormationSlot> slots = formation_slots(shape, n);
  std::vector<size_t> fixed;
  if (robot_joining_ != model::kNoObject) {
    fixed.push_back(n - 1);  // ARI takes the place nearest to it; the members the others
  }
  slot_of_ = assign_slots(participant_positions_, slots, fixed);
  slots_stale_ = false;
  places_.clear();
  for (size_t k = 0; k < n; ++k) {
    places_.push_back(slots[slot_of_[k]]);
  }
}

void GroupNavigation::outsiders_of(const Simulation& simulation, const Human& human,
                                   const Eigen::Vector2d& p) {
  simulation.agent_centres_near(p, human.spec().motion.personal_distance_m, &human, outsiders_,
                                spec_.id);
  if (robot_joining_ != model::kNoObject) {
    // ARI joining is a participant: it keeps the members' spacing, not a stranger's distance.
    const Eigen::Vector2d robot = simulation.ari()->centre();
    outsiders_.erase(std::remove(outsiders_.begin(), outsiders_.end(), robot), outsiders_.end());
  }
}

void GroupNavigation::others_than(size_t i) {
  others_.clear();
  for (size_t j = 0; j < participant_positions_.size(); ++j) {
    if (j != i) {
      others_.push_back(participant_positions_[j]);
    }
  }
}

void GroupNavigation::step_circle(const StepContext& context) {
  Simulation& simulation = context.simulation;
  const double member_personal_distance = member_personal_distance_m();
  const int group_size = static_cast<int>(participant_count());
  const double cohesion_radius = cohesion_radius_m();

  for (size_t i = 0; i < spec_.members.size(); ++i) {
    Human& human = *simulation.mutable_human(spec_.members[i]);
    const HumanMotionParams& params = human.spec().motion;
    const Eigen::Vector2d& p = participant_positions_[i];

    // Participants inside the social space (eq. 3.13), and all other participants (eq. 3.18).
    others_than(i);
    social_neighbours_.clear();
    for (const Eigen::Vector2d& other : others_) {
      if ((other - p).norm() < spec_.social_distance_m) {
        social_neighbours_.push_back(other);
      }
    }
    // Agents outside the group keep the member's own personal distance.
    outsiders_of(simulation, human, p);

    // Eq. 3.9: repulsion (participants at the group's spacing, others at the personal
    // distance), equality and cohesion; and the pull to the member's place on the circle, which
    // D6.4's forces alone do not share out evenly (a newcomer can settle inside the ring).
    const Eigen::Vector2d to_place =
        places_.empty() ? Eigen::Vector2d::Zero() : Eigen::Vector2d(places_[i].position - p);
    const Eigen::Vector2d force =
        spec_.place_gain * to_place +
        social_forces::repulsion_force(p, others_, member_personal_distance) +
        social_forces::repulsion_force(p, outsiders_, params.personal_distance_m) +
        social_forces::equality_force(p, social_neighbours_) +
        social_forces::cohesion_force(p, spec_.centre, cohesion_radius, group_size,
                                      static_cast<int>(social_neighbours_.size()));
    // Eq. 3.10: the orientation vectors are summed and the member turns toward their direction.
    const Eigen::Vector2d facing = social_forces::equality_orientation(p, social_neighbours_) +
                                   social_forces::cohesion_orientation(p, others_);
    double turn = 0.0;
    const double stance = stance_rad(simulation.config().seed, spec_.members[i]);
    if (facing.squaredNorm() > 1e-12) {
      turn =
          core::angle_difference(std::atan2(facing.y(), facing.x()) + stance, human.pose().theta);
    } else if ((spec_.centre - p).squaredNorm() > 1e-12) {
      // A lone member faces the o-space centre.
      const Eigen::Vector2d to_centre = spec_.centre - p;
      turn = core::angle_difference(std::atan2(to_centre.y(), to_centre.x()) + stance,
                                    human.pose().theta);
    }
    move_member(human, force, turn, context.dt_s);
  }
}

void GroupNavigation::step_rows(const StepContext& context) {
  Simulation& simulation = context.simulation;
  // Members keep clear of one another within most of the closest two places' gap, so that
  // they pass each other on the way to their places but do not push at them.
  double closest_places = std::numeric_limits<double>::infinity();
  for (size_t a = 0; a < places_.size(); ++a) {
    for (size_t b = a + 1; b < places_.size(); ++b) {
      closest_places = std::min(closest_places, (places_[a].position - places_[b].position).norm());
    }
  }
  const double member_distance =
      std::isfinite(closest_places) ? kRowSpacingShare * closest_places : 0.0;
  for (size_t i = 0; i < spec_.members.size(); ++i) {
    Human& human = *simulation.mutable_human(spec_.members[i]);
    const Eigen::Vector2d& p = participant_positions_[i];
    const FormationSlot& slot = places_[i];
    others_than(i);
    outsiders_of(simulation, human, p);
    // Cohesion toward the member's place (eq. 3.17 with the place for the o-space ring), and
    // repulsion as in the circle.
    const Eigen::Vector2d to_place = slot.position - p;
    const Eigen::Vector2d force =
        to_place + social_forces::repulsion_force(p, others_, member_distance) +
        social_forces::repulsion_force(p, outsiders_, human.spec().motion.personal_distance_m);
    // Far from the place the member faces where it walks; near it, the o-space.
    const double facing =
        to_place.norm() > kFacePlaceWithinM
            ? std::atan2(to_place.y(), to_place.x())
            : slot.facing_rad + stance_rad(simulation.config().seed, spec_.members[i]);
    move_member(human, force, core::angle_difference(facing, human.pose().theta), context.dt_s);
  }
}

double GroupNavigation::stance_rad(uint64_t seed, model::ObjectId member) const {
  if (spec_.facing_spread_deg <= 0.0) {
    return 0.0;
  }
  // A stream of its own per (group, member).
  const uint64_t index = (static_cast<uint64_t>(spec_.id) << 24) + member;
  return core::rng_for(seed, core::rng_streams::kGroupStance, index)
      .normal(0.0, core::deg_to_rad(spec_.facing_spread_deg));
}

void GroupNavigation::move_member(Human& human, const Eigen::Vector2d& force, double turn_rad,
                                  double dt_s) const {
  // Eq. 3.11-3.12.
  const HumanMotionParams& params = human.spec().motion;
  HumanMotionParams group_params = params;
  group_params.walking_speed_mps = spec_.step_speed_mps;
  human.plan_motion(step_motion(force, group_params).velocity_mps,
                    rotation_step(turn_rad, params, dt_s));
}

}  // namespace ari_social_sim::world
