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

double GroupNavigation::default_member_spacing_m(size_t participants) {
  // Larger groups open out: 1.0 m for three, 1.1 m for four. From five on the spacing of two
  // comes back, so that the o-space radius stays near that of four (0.77-0.78 m) and perception's
  // GCFF (stride 0.6 m) still finds the group whole: a human joining a group of four was counted
  // in 44 of 100 episodes at 1.1 m, 89 at 1.0 m, 100 at 0.9 m (docs/world.md section 4.3).
  constexpr double kPairSpacingM = 0.9;
  constexpr double kGrowthPerParticipantM = 0.1;
  constexpr size_t kGrowsUpTo = 4;
  if (participants > kGrowsUpTo) {
    return kPairSpacingM;
  }
  const size_t beyond_pair = std::max<size_t>(participants, 2) - 2;
  return kPairSpacingM + kGrowthPerParticipantM * static_cast<double>(beyond_pair);
}

double GroupNavigation::spacing_scale_in_use() const {
  return participant_count() <= kSpacingSpreadUpTo ? group_spacing_scale_.value_or(1.0) : 1.0;
}

bool GroupNavigation::stands_in_a_row() const {
  return spec_.arrangement == model::Arrangement::kSideBySide && !kept_as_circle();
}

double GroupNavigation::shoulder_scale_in_use() const {
  if (!stands_in_a_row()) {
    return spacing_scale_in_use();
  }
  return participant_count() <= kSpacingSpreadUpTo ? row_spacing_scale_.value_or(1.0) : 1.0;
}

double GroupNavigation::member_spacing_for(const GroupSpec& spec, size_t participants) {
  return spec.member_spacing_m > 0.0 ? spec.member_spacing_m
                                     : default_member_spacing_m(participants);
}

const MemberManner* GroupNavigation::manner_of(model::ObjectId member) const {
  const auto found = manners_.find(member);
  return found == manners_.end() ? nullptr : &found->second;
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
  const double spacing = member_spacing_for(spec, participants);
  if (arrangement == model::Arrangement::kCircle) {
    return ospace_radius_for(participants, spacing, spec.min_ospace_radius_m);
  }
  return row_distance_for(arrangement, participants, spacing, spec.shoulder_spacing_m);
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
  const double radius = formation_radius_for(
      spec_, kept_as_circle() ? model::Arrangement::kCircle : spec_.arrangement,
      participant_count());
  // A configured radius is kept as it is.
  return spec_.ospace_radius_m > 0.0 ? radius : radius * spacing_scale_in_use();
}

void GroupNavigation::draw_group_spacing(uint64_t seed) {
  if (!group_spacing_scale_) {
    group_spacing_scale_ = group_spacing_scale(seed, spec_.id, spec_.spacing_spread);
    // The same draw, with the row's spread: a wide group stands in a wide row.
    row_spacing_scale_ = group_spacing_scale(
        seed, spec_.id, spec_.row_spacing_spread.value_or(spec_.spacing_spread));
    formation_changed();
  }
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
  manners_.erase(id);
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
  draw_group_spacing(simulation.config().seed);
  update_robot_joining(simulation);
  participant_positions_.clear();
  participant_ids_.clear();
  for (model::ObjectId id : spec_.members) {
    participant_positions_.push_back(simulation.find_human(id)->pose().position);
    participant_ids_.push_back(id);
  }
  if (robot_joining_ != model::kNoObject) {
    participant_positions_.push_back(simulation.ari()->centre());
    participant_ids_.push_back(robot_joining_);
  }
  update_manners(context);
  // Rows are laid out from a bearing; a formation that turns from a circle into rows again
  // takes it anew from where the members stand, unless the spec fixed it.
  const bool circle = kept_as_circle();
  if (!heading_rad_ || (!spec_.heading_rad && !circle && was_circle_)) {
    resolve_heading();
  }
  was_circle_ = circle;
  deal_places(circle);
  place_members_apart();
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
    // The shape changes only with a redeal (set_centre moves the places it has).
    trade_places_while_forming();
    return;
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
  // The group's spacing scale widens or narrows its rows as well as its o-space.
  shape.shoulder_spacing_m = spec_.shoulder_spacing_m * shoulder_scale_in_use();
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

void GroupNavigation::trade_places_while_forming() {
  const size_t n = places_.size();
  bool forming = false;
  for (size_t k = 0; k < n && k < spec_.members.size(); ++k) {
    forming =
        forming || (places_[k].position - participant_positions_[k]).norm() > kFacePlaceWithinM;
  }
  if (!forming || n != participant_positions_.size()) {
    return;
  }
  // Members whose ways to their places cross can block each other for good, body against body;
  // while the group forms, they trade places whenever that shortens the walks.
  std::vector<size_t> fixed;
  if (robot_joining_ != model::kNoObject) {
    fixed.push_back(n - 1);
  }
  const std::vector<size_t> trade = assign_slots(participant_positions_, places_, fixed);
  double walks_now = 0.0;
  double walks_traded = 0.0;
  for (size_t k = 0; k < n; ++k) {
    walks_now += (places_[k].position - participant_positions_[k]).squaredNorm();
    walks_traded += (places_[trade[k]].position - participant_positions_[k]).squaredNorm();
  }
  constexpr double kLeastGainM2 = 0.01;
  if (walks_traded > walks_now - kLeastGainM2) {
    return;
  }
  const std::vector<FormationSlot> places = places_;
  const std::vector<size_t> slot_of = slot_of_;
  for (size_t k = 0; k < n; ++k) {
    places_[k] = places[trade[k]];
    slot_of_[k] = slot_of[trade[k]];
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
    // The member's own spacing and shift move the ring it keeps, for cohesion as for its place.
    const MemberManner& manner = *member_manners_[i];
    const Eigen::Vector2d from_centre = p - spec_.centre;
    const Eigen::Vector2d outward = from_centre.norm() > 1e-9
                                        ? Eigen::Vector2d(from_centre.normalized())
                                        : Eigen::Vector2d::Zero();
    const double own_ring =
        std::max(0.0, cohesion_radius + own_spacing_offset_m(i, from_centre.norm()) +
                          manner.shift().dot(outward));
    const Eigen::Vector2d to_place =
        places_.empty() ? Eigen::Vector2d::Zero() : Eigen::Vector2d(own_places_[i] - p);
    const Eigen::Vector2d force =
        spec_.place_gain * to_place +
        social_forces::repulsion_force(p, others_, member_personal_distance) +
        social_forces::repulsion_force(p, outsiders_, params.personal_distance_m) +
        social_forces::equality_force(p, social_neighbours_) +
        social_forces::cohesion_force(p, spec_.centre, own_ring, group_size,
                                      static_cast<int>(social_neighbours_.size()));
    // Eq. 3.10: the orientation vectors are summed and the member turns toward their direction.
    const Eigen::Vector2d facing = social_forces::equality_orientation(p, social_neighbours_) +
                                   social_forces::cohesion_orientation(p, others_);
    double turn = 0.0;
    if (facing.squaredNorm() > 1e-12) {
      turn = core::angle_difference(own_facing(i, p, std::atan2(facing.y(), facing.x())),
                                    human.pose().theta);
    } else if ((spec_.centre - p).squaredNorm() > 1e-12) {
      // A lone member faces the o-space centre.
      const Eigen::Vector2d to_centre = spec_.centre - p;
      turn = core::angle_difference(own_facing(i, p, std::atan2(to_centre.y(), to_centre.x())),
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
    const Eigen::Vector2d to_place = own_places_[i] - p;
    const Eigen::Vector2d force =
        to_place + social_forces::repulsion_force(p, others_, member_distance) +
        social_forces::repulsion_force(p, outsiders_, human.spec().motion.personal_distance_m);
    // Far from the place the member faces where it walks; near it, the o-space.
    const double facing = to_place.norm() > kFacePlaceWithinM
                              ? std::atan2(to_place.y(), to_place.x())
                              : own_facing(i, p, slot.facing_rad);
    move_member(human, force, core::angle_difference(facing, human.pose().theta), context.dt_s);
  }
}

MannerParams GroupNavigation::manner_params() const {
  MannerParams params;
  // A member's stance is drawn when first met, with the spread of the arrangement then.
  params.facing_spread_rad = core::deg_to_rad(
      stands_in_a_row() ? spec_.row_facing_spread_deg.value_or(spec_.facing_spread_deg)
                        : spec_.facing_spread_deg);
  params.spacing_spread = spec_.spacing_spread;
  params.shift_m = spec_.shift_m;
  params.shift_turn_rad = core::deg_to_rad(spec_.shift_turn_deg);
  params.shift_interval_s = spec_.shift_interval_s;
  return params;
}

void GroupNavigation::update_manners(const StepContext& context) {
  const MannerParams params = manner_params();
  member_manners_.clear();
  for (model::ObjectId id : spec_.members) {
    auto found = manners_.find(id);
    if (found == manners_.end()) {
      found =
          manners_.emplace(id, MemberManner(context.simulation.config().seed, spec_.id, id, params))
              .first;
    }
    found->second.update(context.time_s, id, participant_ids_, params);
    member_manners_.push_back(&found->second);
  }
}

double GroupNavigation::own_spacing_offset_m(size_t i, double from_centre_m) const {
  // The member's scale applies to its share of the spacing (half of it), not to the whole
  // radius: in a circle of six, 20 % of the radius would bring neighbours shoulder to shoulder.
  const double share = std::min(
      from_centre_m, 0.5 * member_spacing_for(spec_, participant_count()) * spacing_scale_in_use());
  const double scale =
      participant_count() <= kSpacingSpreadUpTo ? member_manners_[i]->spacing_scale() : 1.0;
  return (scale - 1.0) * share;
}

void GroupNavigation::place_members_apart() {
  own_places_.clear();
  for (size_t i = 0; i < places_.size() && i < spec_.members.size(); ++i) {
    const FormationSlot& place = places_[i];
    const Eigen::Vector2d from_centre = place.position - spec_.centre;
    const double distance = from_centre.norm();
    const Eigen::Vector2d outward =
        distance > 1e-9 ? Eigen::Vector2d(from_centre / distance) : Eigen::Vector2d::Zero();
    own_places_.push_back(place.position + own_spacing_offset_m(i, distance) * outward +
                          member_manners_[i]->shift());
  }
  // Two members' own places keep kLeastMemberGapM apart: each pair too close is pushed apart
  // evenly along the line between them, a few passes so that a push does not leave a third
  // member too close in a row.
  constexpr int kPasses = 3;
  for (int pass = 0; pass < kPasses; ++pass) {
    for (size_t a = 0; a < own_places_.size(); ++a) {
      for (size_t b = a + 1; b < own_places_.size(); ++b) {
        const Eigen::Vector2d apart = own_places_[b] - own_places_[a];
        const double gap = apart.norm();
        if (gap < kLeastMemberGapM && gap > 1e-9) {
          const Eigen::Vector2d push = 0.5 * (kLeastMemberGapM - gap) * apart / gap;
          own_places_[a] -= push;
          own_places_[b] += push;
        }
      }
    }
  }
}

double GroupNavigation::own_facing(size_t i, const Eigen::Vector2d& p,
                                   double formation_facing_rad) const {
  const MemberManner& manner = *member_manners_[i];
  double facing = formation_facing_rad + manner.stance_rad() + manner.shift_turn_rad();
  const auto attended =
      std::find(participant_ids_.begin(), participant_ids_.end(), manner.attended());
  if (attended != participant_ids_.end()) {
    const Eigen::Vector2d to_attended =
        participant_positions_[static_cast<size_t>(attended - participant_ids_.begin())] - p;
    facing += spec_.attention * core::angle_difference(std::atan2(to_attended.y(), to_attended.x()),
                                                       formation_facing_rad);
  }
  return facing;
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
