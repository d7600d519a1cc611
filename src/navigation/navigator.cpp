#include "ari_social_sim/navigation/navigator.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/core/config_check.hpp"
#include "ari_social_sim/core/format_text.hpp"
#include "ari_social_sim/navigation/goal_request.hpp"
#include "ari_social_sim/navigation/navigation_errors.hpp"
#include "ari_social_sim/navigation/signed_distance_field.hpp"
#include "ari_social_sim/navigation/social_spaces.hpp"

namespace ari_social_sim::navigation {

namespace {

std::string format_seconds(double s) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.1f s", s);
  return text;
}

}  // namespace

Navigator::Navigator(const NavigationConfig& config, const model::OccupancyGrid& map)
    : config_(core::validated(config)),
      footprint_(FootprintModel::covering(model::AriFootprint{}, config.mpc.footprint_circles)),
      sdf_(signed_distance_field(map)),
      goal_finder_(config.goal_finder, footprint_, config.mpc.personal_space),
      mpc_(config.mpc, footprint_),
      outline_(footprint_.outline(0.1)) {}

void Navigator::start(const NavigationTarget& target, const PerceivedScene& scene,
                      const RobotObservation& robot, double time_s) {
  check_target(target);
  GoalSearch search = goal_finder_.find(target, scene, sdf_, robot.pose);
  if (const auto* failure = std::get_if<GoalFailure>(&search)) {
    refuse_goal(*failure);
  }
  Goal& goal = std::get<Goal>(search);
  std::vector<CostDisc> discs = cost_discs(scene, goal);
  FieldSearch field = field_to(goal, robot.pose, discs);
  if (const auto* failure = std::get_if<GoalFailure>(&field)) {
    refuse_goal(*failure);
  }
  field_discs_ = std::move(discs);
  goal_ = std::move(goal);
  geodesic_ = std::move(std::get<std::unique_ptr<GeodesicField>>(field));
  target_ = target;
  target_members_.clear();
  target_person_seen_at_.reset();
  follow_relabelled_group(scene);
  follow_relabelled_person(scene);
  state_ = NavigationState::kActive;
  target_seen_s_ = time_s;
  aligning_ = false;
  jump_since_s_.reset();
  best_distance_m_ = geodesic_->cost(robot.pose.position);
  best_distance_time_s_ = time_s;
  patience_clock_s_ = time_s;
  mpc_.reset();
}

void Navigator::follow_relabelled_group(const PerceivedScene& scene) {
  auto* target = std::get_if<GroupTarget>(&*target_);
  if (target == nullptr) {
    return;
  }
  if (const GroupEstimate* group = scene.find_group(target->group_id)) {
    target_members_ = group->members;
    return;
  }
  const GroupEstimate* best = nullptr;
  size_t best_shared = 1;
  for (const GroupEstimate& group : scene.groups) {
    const auto shared = static_cast<size_t>(
        std::count_if(group.members.begin(), group.members.end(), [&](const std::string& id) {
          return std::find(target_members_.begin(), target_members_.end(), id) !=
                 target_members_.end();
        }));
    if (shared > best_shared) {
      best = &group;
      best_shared = shared;
    }
  }
  if (best != nullptr) {
    target->group_id = best->id;
    target_members_ = best->members;
  }
}

void Navigator::follow_relabelled_person(const PerceivedScene& scene) {
  std::string* person_id = nullptr;
  if (auto* person = std::get_if<PersonTarget>(&*target_)) {
    person_id = &person->person_id;
  } else if (auto* member = std::get_if<GroupOfPersonTarget>(&*target_)) {
    person_id = &member->person_id;
  }
  if (person_id == nullptr) {
    return;
  }
  // Joining a person's group needs them in a group. Perception may track one human twice (an
  // anonymous body and the person their face was recognised as) and group only one of them.
  const bool needs_group = std::holds_alternative<GroupOfPersonTarget>(*target_);
  if (const PersonEstimate* person = scene.find_person(*person_id)) {
    target_person_seen_at_ = person->position;
    const GroupEstimate* group = scene.group_of(*person_id);
    if (group != nullptr) {
      target_members_ = group->members;
    }
    if (!needs_group || group != nullptr) {
      return;
    }
  }
  if (!target_person_seen_at_) {
    return;
  }
  const PersonEstimate* nearest = nullptr;
  double nearest_m = kReidentifiedWithinM;
  for (const PersonEstimate& person : scene.people) {
    const double distance_m = (person.position - *target_person_seen_at_).norm();
    const bool usable = !needs_group || scene.group_of(person.id) != nullptr;
    if (usable && distance_m <= nearest_m) {
      nearest = &person;
      nearest_m = distance_m;
    }
  }
  if (nearest == nullptr && needs_group) {
    nearest = newcomer_in_target_group(scene);
  }
  if (nearest != nullptr) {
    *person_id = nearest->id;
    target_person_seen_at_ = nearest->position;
  }
}

const PersonEstimate* Navigator::newcomer_in_target_group(const PerceivedScene& scene) const {
  const auto remembered = [&](const std::string& id) {
    return std::find(target_members_.begin(), target_members_.end(), id) != target_members_.end();
  };
  const PersonEstimate* nearest = nullptr;
  double nearest_m = 0.0;
  for (const GroupEstimate& group : scene.groups) {
    const auto kept =
        static_cast<size_t>(std::count_if(group.members.begin(), group.members.end(), remembered));
    // Every other member is still there and nobody is missing: the target's place is taken by
    // an id the group did not have, the target's new one. A group that shrank lost the target.
    if (kept + 1 < target_members_.size() || group.members.size() < target_members_.size()) {
      continue;
    }
    for (const std::string& id : group.members) {
      const PersonEstimate* person = scene.find_person(id);
      if (person == nullptr || remembered(id)) {
        continue;
      }
      const double distance_m = (person->position - *target_person_seen_at_).norm();
      if (nearest == nullptr || distance_m < nearest_m) {
        nearest = person;
        nearest_m = distance_m;
      }
    }
  }
  return nearest;
}

void Navigator::cancel() {
  state_ = NavigationState::kIdle;
  target_.reset();
}

std::vector<CostDisc> Navigator::cost_discs(const PerceivedScene& scene, const Goal& goal) const {
  // People standing still and groups stand in the way as areas to go around; walking people are
  // the MPC's, which predicts them. The person approached and the members joined keep only their
  // body plus ARI's inscribed radius, so the way goes round them but reaches the goal beside them.
  constexpr double kStandingSpeed = 0.3;  // m/s
  const GeodesicParams& g = config_.navigator.geodesic;
  std::vector<CostDisc> discs;
  if (g.person_cost > 0.0) {
    for (const PersonEstimate& person : scene.people) {
      if (person.velocity.norm() >= kStandingSpeed) {
        continue;
      }
      const bool is_target = goal.is_target(person.id);
      discs.push_back({person.position,
                       config_.mpc.personal_space.person_radius_m + g.inscribed_radius_m +
                           (is_target ? 0.0 : g.person_clearance_m),
                       g.person_cost});
    }
  }
  // Other groups' whole circle; the joined group's o-space only, which ARI's goal at the rim of
  // barely enters, so the way comes in through the gap rather than across the o-space.
  if (g.group_cost > 0.0) {
    for (const GroupEstimate& group : scene.groups) {
      const double radius = group.id == goal.group_id
                                ? ospace_radius(group, config_.mpc.personal_space)
                                : group.radius_m;
      discs.push_back({group.centre, radius, g.group_cost});
    }
  }
  return discs;
}

bool Navigator::discs_changed(const std::vector<CostDisc>& discs) const {
  constexpr double kMoved = 0.2;  // m
  if (discs.size() != field_discs_.size()) {
    return true;
  }
  for (size_t i = 0; i < discs.size(); ++i) {
    if ((discs[i].centre - field_discs_[i].centre).norm() > kMoved ||
        std::abs(discs[i].radius_m - field_discs_[i].radius_m) > kMoved) {
      return true;
    }
  }
  return false;
}

Navigator::FieldSearch Navigator::field_to(const Goal& goal, const core::Pose2& robot,
                                           const std::vector<CostDisc>& discs) const {
  auto field =
      std::make_unique<GeodesicField>(sdf_, goal.pose.position, config_.navigator.geodesic, discs);
  if (!field->reachable(goal.pose.position)) {
    return GoalFailure{GoalFailure::Kind::kUnreachable,
                       "goal " + core::point_text(goal.pose.position) +
                           " is too close to walls or furniture for ARI to reach"};
  }
  if (!field->reachable(robot.position)) {
    return GoalFailure{GoalFailure::Kind::kUnreachable,
                       "no collision-free path from ARI at " + core::point_text(robot.position) +
                           " to the goal " + core::point_text(goal.pose.position)};
  }
  return field;
}

std::optional<GoalFailure> Navigator::adopt_goal(const Goal& goal, const core::Pose2& robot,
                                                 const PerceivedScene& scene) {
  // A goal that shifts by less than goal_update_distance and goal_update_angle keeps the pose
  // aimed at: the members of a group settling around ARI move its place by a few centimetres at
  // a time, and a pose that followed them would drift away from the geodesic field's goal, to
  // which the MPC's progress term leads; ARI then stalled short of the pose judged for arrival.
  const bool moved = (goal.pose.position - goal_->pose.position).norm() >
                         config_.navigator.goal_update_distance_m ||
                     std::abs(core::angle_difference(goal.pose.theta, goal_->pose.theta)) >
                         config_.navigator.goal_update_angle;
  Goal adopted = goal;
  if (!moved) {
    adopted.pose = goal_->pose;
  }
  std::vector<CostDisc> discs = cost_discs(scene, adopted);
  if (moved || discs_changed(discs)) {
    const double distance_before = geodesic_->cost(robot.position);
    FieldSearch field = field_to(adopted, robot, discs);
    if (auto* failure = std::get_if<GoalFailure>(&field)) {
      return std::move(*failure);
    }
    geodesic_ = std::move(std::get<std::unique_ptr<GeodesicField>>(field));
    field_discs_ = std::move(discs);
    // The progress watchdog's best distance moves with the field, by as much as ARI's own
    // distance just did: a goal that moved away (to another gap, with a group perception now
    // sees a little differently) would otherwise leave ARI short of the best it reached toward
    // the old one, and abort a run still closing in; a goal that jitters back and forth shifts
    // it back and forth and never counts as progress.
    best_distance_m_ += geodesic_->cost(robot.position) - distance_before;
  }
  goal_ = std::move(adopted);
  return std::nullopt;
}

std::optional<GoalFailure> Navigator::follow_target(double time_s, const core::Pose2& robot,
                                                    const PerceivedScene& scene) {
  GoalSearch search = goal_finder_.find(*target_, scene, sdf_, robot, goal_);
  if (auto* failure = std::get_if<GoalFailure>(&search)) {
    return std::move(*failure);
  }
  const Goal& found = std::get<Goal>(search);
  target_seen_s_ = time_s;
  // A goal that jumps (another gap, another side of the person) must hold for a while before
  // ARI follows it: perception's noise can make a group look different for a frame or two.
  const bool jumped = (found.pose.position - goal_->pose.position).norm() >
                      config_.navigator.goal_switch_distance_m;
  if (!jumped) {
    jump_since_s_.reset();
    return adopt_goal(found, robot, scene);
  }
  if (!jump_since_s_) {
    jump_since_s_ = time_s;
  } else if (time_s - *jump_since_s_ >= config_.navigator.goal_switch_time_s) {
    jump_since_s_.reset();
    return adopt_goal(found, robot, scene);
  }
  return std::nullopt;
}

NavigatorStep Navigator::finish(NavigationState state, const std::string& reason) {
  state_ = state;
  NavigatorStep step;
  step.state = state;
  step.reason = reason;
  step.phase = state == NavigationState::kSucceeded ? "arrived" : "aborted";
  step.command.pan_rad = problem_.start.pan;
  return step;
}

NavigatorStep Navigator::update(double time_s, const RobotObservation& robot,
                                const PerceivedScene& scene) {
  NavigatorStep step;
  step.state = state_;
  step.command.pan_rad = robot.pan_rad;
  if (state_ != NavigationState::kActive) {
    return step;
  }
  problem_.start.pan = robot.pan_rad;

  // Resolve the target into a goal; keep the last goal while the target is briefly unseen.
  follow_relabelled_group(scene);
  follow_relabelled_person(scene);
  const std::optional<GoalFailure> failure = follow_target(time_s, robot.pose, scene);
  const bool target_visible = !failure;
  if (failure) {
    const double unseen_s = time_s - target_seen_s_;
    const bool lost = unseen_s > config_.navigator.target_lost_timeout_s;
    if (failure->kind == GoalFailure::Kind::kUnknownTarget && lost) {
      return finish(NavigationState::kAborted, describe(*target_) + " lost for " +
                                                   format_seconds(unseen_s) + " (" +
                                                   failure->reason + ")");
    }
    // A pose stays unreachable; a person or group may make room again (or perception may have
    // misjudged them for a moment): keep the last goal up to the lost-target timeout.
    if (failure->kind == GoalFailure::Kind::kUnreachable &&
        (std::holds_alternative<PoseTarget>(*target_) || lost)) {
      return finish(NavigationState::kAborted, failure->reason);
    }
  }

  // Arrival, judged on base_footprint against the goal pose.
  const double heading_error =
      std::abs(core::angle_difference(goal_->pose.theta, robot.pose.theta));
  const bool at_position = at_goal_position(robot.pose);
  step.distance_to_goal_m = geodesic_->cost(robot.pose.position);
  // Arriving where the target was last seen counts: a member hidden behind another as ARI
  // steps into the gap is still there.
  if (at_position && heading_error <= config_.navigator.yaw_tolerance) {
    NavigatorStep done = finish(NavigationState::kSucceeded, "");
    done.distance_to_goal_m = step.distance_to_goal_m;
    done.command.pan_rad = robot.pan_rad;
    return done;
  }

  // Progress watchdog on the geodesic distance.
  if (step.distance_to_goal_m < best_distance_m_ - config_.navigator.progress_distance_m) {
    best_distance_m_ = step.distance_to_goal_m;
    best_distance_time_s_ = time_s;
    if (patience(time_s) == 1.0 || !inside_bystander_space(robot.pose, scene)) {
      patience_clock_s_ = time_s;
    }
  } else if (!at_position &&
             time_s - best_distance_time_s_ > config_.navigator.progress_timeout_s) {
    return finish(NavigationState::kAborted,
                  "no progress toward " + describe(*target_) + " for " +
                      format_seconds(time_s - best_distance_time_s_) + " (" +
                      core::point_text(robot.pose.position) + ", " +
                      core::coordinate_text(step.distance_to_goal_m) + " m to go)");
  }

  build_problem(time_s, robot, scene);
  plan_ = mpc_.solve(problem_);
  step.replanned = true;
  step.command = {plan_.linear_mps(), plan_.angular_rps(), plan_.pan_target()};
  step.phase = !target_visible ? "waiting for the target" : aligning_ ? "aligning" : "approaching";
  return step;
}

bool Navigator::at_goal_position(const core::Pose2& robot) const {
  const Eigen::Vector2d to_goal = goal_->pose.position - robot.position;
  if (to_goal.norm() > config_.navigator.goal_tolerance_m) {
    return false;
  }
  // A join's goal faces the o-space centre with ARI's body on the participants' ring: stopping
  // short of it along that heading leaves ARI outside the ring, where F-formation detection
  // (GCFF, whose o-space point lies a stride ahead of each body) no longer counts it a member,
  // so the ring side of the tolerance is tighter.
  return goal_->group_id.empty() ||
         to_goal.dot(goal_->pose.heading()) <= config_.navigator.join_shortfall_tolerance_m;
}

double Navigator::patience(double time_s) const {
  const NavigatorConfig& nav = config_.navigator;
  const double stalled_s = time_s - patience_clock_s_ - nav.patience_s;
  return stalled_s > 0.0 ? std::pow(0.5, stalled_s / nav.patience_halving_s) : 1.0;
}

bool Navigator::inside_bystander_space(const core::Pose2& robot,
                                       const PerceivedScene& scene) const {
  return std::any_of(scene.people.begin(), scene.people.end(), [&](const PersonEstimate& person) {
    return !goal_->is_target(person.id) &&
           outline_inside_personal_space(outline_, robot, person, config_.mpc.personal_space);
  });
}

void Navigator::build_problem(double time_s, const RobotObservation& robot,
                              const PerceivedScene& scene) {
  problem_.start.position = robot.pose.position;
  problem_.start.theta = robot.pose.theta;
  problem_.start.pan = robot.pan_rad;
  problem_.start_linear_mps = robot.linear_mps;
  problem_.start_angular_rps = robot.angular_rps;
  problem_.start_pan_rps = robot.pan_rps;
  problem_.sdf = &sdf_;
  problem_.geodesic = geodesic_.get();
  problem_.goal = goal_->pose;
  // Turning on the spot once at the goal position, until pushed out to twice the tolerance: the
  // turn about base_footprint may shift it a little, and the phase must not flicker. Once turned
  // but still outside the tolerance, ARI drives again: turning on the spot cannot close a
  // sideways offset, and the arrival heading would hold it there.
  const double position_error = (robot.pose.position - goal_->pose.position).norm();
  const double heading_error =
      std::abs(core::angle_difference(goal_->pose.theta, robot.pose.theta));
  const double tolerance = config_.navigator.goal_tolerance_m;
  if (at_goal_position(robot.pose)) {
    aligning_ = true;
  } else if (position_error > 2.0 * tolerance || heading_error <= config_.navigator.yaw_tolerance) {
    aligning_ = false;
  }
  problem_.at_goal_position = aligning_;
  problem_.look_at = goal_->look_at;
  // The person approached or the members joined keep a share of their personal space while ARI
  // is far, so it comes in from the front rather than brushing past them, fading to nothing over
  // the last metres where ARI must stand within it: from the fade distance to half of it.
  const double distance = geodesic_->cost(robot.pose.position);
  const double fade_start = config_.mpc.target_space_fade_m;
  const double fade_end = 0.5 * fade_start;
  const double target_scale = config_.mpc.target_space_scale *
                              std::clamp((distance - fade_end) / (fade_start - fade_end), 0.0, 1.0);
  // Patience: when someone's space blocks the only way (a person standing in a doorway), ARI
  // waits, then claims the way bit by bit, halving the personal-space weights every
  // patience_halving seconds; people step aside from a robot pressing on.
  const double patience = this->patience(time_s);
  problem_.people.clear();
  for (const PersonEstimate& person : scene.people) {
    const bool is_target = goal_->is_target(person.id);
    problem_.people.push_back({person, patience * (is_target ? target_scale : 1.0)});
  }
  problem_.groups.clear();
  for (const GroupEstimate& group : scene.groups) {
    problem_.groups.push_back({group, group.id == goal_->group_id});
  }
}

}  // namespace ari_social_sim::navigation
