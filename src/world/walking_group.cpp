#include "ari_social_sim/world/walking_group.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>

#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/core/config_check.hpp"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/world/human.hpp"
#include "ari_social_sim/world/simulation.hpp"
#include "ari_social_sim/world/social_forces.hpp"
#include "ari_social_sim/world/step_motion.hpp"

namespace ari_social_sim::world {
namespace {

// 1/s: a member walks with its place's velocity plus this gain times the way to the place, so it
// follows the moving place without the lag a pull alone would leave (speed / gain).
constexpr double kPlaceGainPerS = 2.0;
// Members repel one another within this share of the spacing, as the rows of a conversation
// group do (kRowSpacingShare): neighbours at their places do not push each other.
constexpr double kMemberRepulsionShare = kRowSpacingShare;
// m of route ahead of the leader that must have room for the row before the group walks abreast:
// about two steps, so the group falls into a line before a door rather than in it.
constexpr double kLookAheadM = 1.5;
// m of route behind the last member's place that must have room too: the group re-forms once the
// last member is through.
constexpr double kLookBehindM = 0.5;
// A member this close (m) to its place at the goal has arrived.
constexpr double kArrivedM = 0.3;

Eigen::Vector2d unit(double theta) {
  return {std::cos(theta), std::sin(theta)};
}

}  // namespace

bool WalkingGroupSpec::lists_a_member_twice() const {
  return std::set<model::ObjectId>(members.begin(), members.end()).size() != members.size();
}

void WalkingGroupSpec::validate() const {
  core::check_fields<core::RequestError>(*this, "");
}

WalkingGroup::WalkingGroup(const WalkingGroupSpec& spec, WalkingRoute route, double body_radius_m,
                           const std::vector<Eigen::Vector2d>& member_positions)
    : spec_(spec), route_(std::move(route)), body_radius_m_(body_radius_m) {
  formation_ = formation_for_route();
  order_members(formation_, member_positions);
}

double WalkingGroup::heading_rad() const {
  // A group created at its goal has no way to walk: it faces the goal's heading.
  return route_.length_m() > 1e-6 ? route_.heading_at(progress_m_) : spec_.goal.theta;
}

double WalkingGroup::abreast_half_width_m(size_t count) const {
  const double row = count > 1 ? 0.5 * static_cast<double>(count - 1) * spec_.spacing_m : 0.0;
  return row + body_radius_m_ + kWalkingWallMarginM;
}

GroupSpec WalkingGroup::conversation() const {
  GroupSpec group;
  group.id = spec_.id;
  group.members = spec_.members;
  group.centre = spec_.goal.position;
  group.arrangement = spec_.arrangement;
  return group;
}

void WalkingGroup::remove_member(model::ObjectId id) {
  const auto it = std::find(spec_.members.begin(), spec_.members.end(), id);
  if (it == spec_.members.end()) {
    return;
  }
  const size_t gone = static_cast<size_t>(it - spec_.members.begin());
  const size_t freed = slot_of_[gone];
  spec_.members.erase(it);
  slot_of_.erase(slot_of_.begin() + static_cast<std::ptrdiff_t>(gone));
  // The others close the gap: places stay numbered 0..n-1 in the same order.
  for (size_t& slot : slot_of_) {
    slot -= slot > freed ? 1 : 0;
  }
}

WalkingFormation WalkingGroup::formation_for_route() const {
  const size_t n = spec_.members.size();
  if (spec_.formation == WalkingFormation::kLine || n < 2) {
    return spec_.formation;
  }
  // At the goal the row forms where the leader stands, if there is room for it there.
  const bool at_goal = progress_m_ >= route_.length_m();
  const double behind =
      at_goal ? kLookBehindM : static_cast<double>(n - 1) * spec_.line_spacing_m + kLookBehindM;
  const double room = route_.min_clearance_m(progress_m_ - behind, progress_m_ + kLookAheadM);
  return room >= abreast_half_width_m(n) ? WalkingFormation::kSideBySide : WalkingFormation::kLine;
}

void WalkingGroup::order_members(WalkingFormation formation,
                                 const std::vector<Eigen::Vector2d>& positions) {
  // Abreast from left to right, in a line from front to back: each keeps the side or rank it
  // has, so nobody crosses another's way.
  const double theta = heading_rad();
  const Eigen::Vector2d axis = formation == WalkingFormation::kSideBySide
                                   ? Eigen::Vector2d(-std::sin(theta), std::cos(theta))
                                   : unit(theta);
  const Eigen::Vector2d origin = leader();
  std::vector<size_t> order(positions.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return (positions[a] - origin).dot(axis) > (positions[b] - origin).dot(axis);
  });
  slot_of_.assign(positions.size(), 0);
  for (size_t rank = 0; rank < order.size(); ++rank) {
    slot_of_[order[rank]] = rank;
  }
}

std::vector<FormationSlot> WalkingGroup::places(WalkingFormation formation, double s_m) const {
  const size_t n = spec_.members.size();
  std::vector<FormationSlot> slots(n);
  const Eigen::Vector2d centre = route_.point_at(s_m);
  const double theta = route_.length_m() > 1e-6 ? route_.heading_at(s_m) : spec_.goal.theta;
  const Eigen::Vector2d left(-std::sin(theta), std::cos(theta));
  for (size_t i = 0; i < n; ++i) {
    const double k = static_cast<double>(slot_of_[i]);
    if (formation == WalkingFormation::kSideBySide) {
      // A row across the walking direction, centred on the leader, slot 0 leftmost.
      const double lateral = (0.5 * static_cast<double>(n - 1) - k) * spec_.spacing_m;
      slots[i] = {centre + lateral * left, theta};
    } else {
      // One behind the other along the route, so the line bends with it through a door.
      const double s = s_m - k * spec_.line_spacing_m;
      slots[i] = {route_.point_at(s),
                  route_.length_m() > 1e-6 ? route_.heading_at(s) : spec_.goal.theta};
    }
  }
  return slots;
}

void WalkingGroup::step(const StepContext& context) {
  Simulation& simulation = context.simulation;
  positions_.clear();
  for (model::ObjectId id : spec_.members) {
    positions_.push_back(simulation.find_human(id)->pose().position);
  }

  // The leader slows while a member lags behind its place, and waits at twice wait_distance.
  double lag = 0.0;
  const std::vector<FormationSlot> now = places(formation_, progress_m_);
  for (size_t i = 0; i < positions_.size(); ++i) {
    lag = std::max(lag, (now[i].position - positions_[i]).dot(unit(now[i].facing_rad)));
  }
  const double pace = std::clamp(2.0 - lag / spec_.wait_distance_m, 0.0, 1.0);
  waiting_ = !arrived_ && pace <= 0.0;
  const double before = progress_m_;
  progress_m_ = std::min(route_.length_m(), progress_m_ + spec_.speed_mps * pace * context.dt_s);
  // The places' speed: none once the leader stands at the goal.
  const double speed = (progress_m_ - before) / context.dt_s;

  // Where the way narrows an abreast group falls into a line, and re-forms after it.
  const WalkingFormation wanted = formation_for_route();
  if (wanted != formation_) {
    formation_ = wanted;
    order_members(formation_, positions_);
  }

  // Each member walks with its place and toward it, clear of the others (D6.4 eq. 3.6) and of
  // outsiders at its own personal distance.
  const std::vector<FormationSlot> slots = places(formation_, progress_m_);
  const double member_distance =
      kMemberRepulsionShare *
      (formation_ == WalkingFormation::kSideBySide ? spec_.spacing_m : spec_.line_spacing_m);
  bool all_placed = true;
  for (size_t i = 0; i < spec_.members.size(); ++i) {
    Human& human = *simulation.mutable_human(spec_.members[i]);
    const HumanMotionParams& params = human.spec().motion;
    const Eigen::Vector2d& p = positions_[i];
    others_.clear();
    for (size_t j = 0; j < positions_.size(); ++j) {
      if (j != i) {
        others_.push_back(positions_[j]);
      }
    }
    simulation.agent_centres_near(p, params.personal_distance_m, &human, outsiders_, spec_.id);
    const Eigen::Vector2d to_place = slots[i].position - p;
    all_placed = all_placed && to_place.norm() < kArrivedM;
    Eigen::Vector2d velocity =
        speed * unit(slots[i].facing_rad) +
        kPlaceGainPerS *
            (to_place + social_forces::repulsion_force(p, others_, member_distance) +
             social_forces::repulsion_force(p, outsiders_, params.personal_distance_m));
    // On the way nobody walks back to a place behind them: one ahead of its place waits for it.
    // At the goal they step into their places whichever way they are.
    const double forward = velocity.dot(unit(slots[i].facing_rad));
    if (forward < 0.0 && progress_m_ < route_.length_m()) {
      velocity -= forward * unit(slots[i].facing_rad);
    }
    const double top = velocity.norm();
    if (top > params.max_speed_mps) {
      velocity *= params.max_speed_mps / top;
    }
    // Members face the way they walk, and the goal's heading once there.
    const double facing = arrived_ ? spec_.goal.theta : slots[i].facing_rad;
    human.plan_motion(velocity, rotation_step(core::angle_difference(facing, human.pose().theta),
                                              params, context.dt_s));
  }
  arrived_ = arrived_ || (progress_m_ >= route_.length_m() && all_placed);
}

}  // namespace ari_social_sim::world
