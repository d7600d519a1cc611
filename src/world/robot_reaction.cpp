#include "ari_social_sim/world/robot_reaction.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/core/check.hpp"
#include "ari_social_sim/core/config_check.hpp"
#include "ari_social_sim/core/error.hpp"
#include "ari_social_sim/world/human.hpp"
#include "ari_social_sim/world/simulation.hpp"

namespace ari_social_sim::world {
namespace {

// A reaction ends this much beyond the distance that started it, so a person at the edge does not
// flicker in and out of it from one step to the next.
constexpr double kHysteresisM = 0.5;
// Within this of a place a person counts as there (arrival of a sidestep or of the way back).
constexpr double kArrivedM = 0.05;
// Speeds of the slow moves, as a share of the walking speed: walking up to ARI and backing off
// are a careful approach, not a walk.
constexpr double kCarefulShare = 0.6;
// A group member's bounded sidestep or step away, as a share of the walking speed.
constexpr double kMemberShare = 0.5;
// 1/s: how hard a blocker closes on its place in front of ARI, on top of ARI's own velocity.
constexpr double kBlockGain = 2.0;
// m of floor a probed place keeps clear of walls and furniture beyond the body's radius.
constexpr double kFreeMarginM = 0.05;
// Directions an avoiding person considers when the way straight away from ARI is shut.
constexpr int kAvoidDirections = 16;

Eigen::Vector2d left_of(const Eigen::Vector2d& direction) {
  return {-direction.y(), direction.x()};
}

double bearing(const Eigen::Vector2d& from, const Eigen::Vector2d& to) {
  const Eigen::Vector2d d = to - from;
  return std::atan2(d.y(), d.x());
}

// The footprint's point nearest to `point` (m, map frame): the point itself when inside.
Eigen::Vector2d nearest_footprint_point(const RobotView& robot, const Eigen::Vector2d& point) {
  const Eigen::Vector2d local = core::Pose2{point, 0.0}.relative_to(robot.pose).position;
  const Eigen::Vector2d clamped(
      std::clamp(local.x(), robot.footprint.rear_x_m, robot.footprint.front_x_m),
      std::clamp(local.y(), -robot.footprint.half_width_m, robot.footprint.half_width_m));
  return robot.pose.transform(clamped);
}

// Unit vector from ARI's nearest point to `point`; from its centre when `point` is inside it.
Eigen::Vector2d away_from(const RobotView& robot, const Eigen::Vector2d& point) {
  Eigen::Vector2d away = point - nearest_footprint_point(robot, point);
  if (away.norm() < 1e-6) {
    away = point - robot.centre();
  }
  return away.norm() < 1e-9 ? robot.travel_direction() : away.normalized();
}

// True when a body of `radius_m` can stand at every point of the segment from `from` to `to`
// (probed every 0.2 m) clear of walls, furniture and the floor's edge.
bool way_is_free(const Simulation& simulation, const Eigen::Vector2d& from,
                 const Eigen::Vector2d& to, double radius_m) {
  const double length = (to - from).norm();
  const int samples = 1 + static_cast<int>(std::ceil(length / 0.2));
  for (int i = 1; i <= samples; ++i) {
    const Eigen::Vector2d at = from + (to - from) * (static_cast<double>(i) / samples);
    if (simulation.static_clearance_m(at, radius_m) < kFreeMarginM) {
      return false;
    }
  }
  return true;
}

// A velocity toward `target` at up to `speed`, slowing within 0.3 m so it does not overshoot at a
// 0.05 s step; zero once within kArrivedM / 2.
Eigen::Vector2d velocity_toward(const Eigen::Vector2d& from, const Eigen::Vector2d& target,
                                double speed) {
  const Eigen::Vector2d d = target - from;
  const double n = d.norm();
  if (n < 0.5 * kArrivedM) {
    return Eigen::Vector2d::Zero();
  }
  return d / n * speed * std::min(1.0, n / 0.3);
}

}  // namespace

const char* reaction_name(ReactionProfile profile) {
  return core::choice_name(profile, kReactionProfiles);
}

void ReactionParams::validate() const {
  core::check_fields<core::RequestError>(*this, "");
}

double RobotView::distance_to(const Eigen::Vector2d& point) const {
  return (point - nearest_footprint_point(*this, point)).norm();
}

Eigen::Vector2d RobotView::travel_direction() const {
  return linear_mps < 0.0 ? Eigen::Vector2d(-pose.heading()) : pose.heading();
}

PathOffset path_offset(const RobotView& robot, const Eigen::Vector2d& point) {
  // Reversing, ARI's leading edge is its rear, and "left" flips with the direction of travel.
  const bool reversing = robot.linear_mps < 0.0;
  const Eigen::Vector2d direction = robot.travel_direction();
  const double leading_x = reversing ? robot.footprint.rear_x_m : robot.footprint.front_x_m;
  const Eigen::Vector2d edge = robot.pose.transform({leading_x, 0.0});
  const Eigen::Vector2d d = point - edge;
  return {d.dot(direction), d.dot(left_of(direction))};
}

bool in_robot_corridor(const RobotView& robot, const Eigen::Vector2d& point,
                       const ReactionParams& params) {
  const double speed = std::abs(robot.linear_mps);
  if (speed <= params.moving_speed_mps) {
    return false;
  }
  const PathOffset offset = path_offset(robot, point);
  const double length = robot.footprint.front_x_m - robot.footprint.rear_x_m;
  const double ahead = params.corridor_time_s * speed + params.corridor_extra_m;
  return offset.ahead_m > -length && offset.ahead_m < ahead &&
         std::abs(offset.lateral_m) < robot.footprint.half_width_m + params.corridor_margin_m;
}

RobotReaction::RobotReaction(ReactionProfile profile, const ReactionParams& params, core::Rng rng)
    : profile_(profile), params_(params), rng_(rng) {}

void RobotReaction::set_profile(ReactionProfile profile) {
  profile_ = profile;
  reset();
  gaze_.reset();
  next_gaze_change_s_.reset();
}

void RobotReaction::reset() {
  phase_ = Phase::kIdle;
  motion_ = ReactionMotion{};
}

void RobotReaction::step(Object& owner, const StepContext& context) {
  const auto& human = static_cast<const Human&>(owner);
  motion_ = ReactionMotion{};
  const Ari* ari = context.simulation.ari();
  if (profile_ == ReactionProfile::kIgnore || ari == nullptr ||
      human.motion_mode() == MotionMode::kDirect) {
    // A person driven by a direct velocity follows its client, not ARI.
    phase_ = Phase::kIdle;
    gaze_.reset();
    next_gaze_change_s_.reset();
    return;
  }
  const RobotView robot{ari->id(), ari->pose(), ari->spec().footprint, ari->linear_mps()};
  const double now_s = context.time_s + context.dt_s;
  const double distance = robot.distance_to(human.pose().position);
  const bool noticed = distance < params_.notice_distance_m;
  update_gaze(human, robot, now_s, noticed);
  if (human.motion_mode() == MotionMode::kGroup) {
    plan_member(human, robot);
  } else {
    plan_alone(human, context, robot);
  }
  ARI_DCHECK(motion_.velocity_mps.allFinite());
}

void RobotReaction::update_gaze(const Object& owner, const RobotView& robot, double now_s,
                                bool noticed) {
  if (!noticed) {
    gaze_.reset();
    next_gaze_change_s_.reset();
    return;
  }
  // Gaze events as GazeGenerator's: exponential dwells timed from the drawn change, each at ARI
  // with the profile's share, so that share is the share of time spent looking at ARI.
  if (!next_gaze_change_s_ || now_s + 1e-9 >= *next_gaze_change_s_) {
    const double share = profile_ == ReactionProfile::kYield     ? params_.yield_look_share
                         : profile_ == ReactionProfile::kCurious ? params_.curious_look_share
                         : profile_ == ReactionProfile::kAvoid   ? params_.avoid_look_share
                                                                 : params_.block_look_share;
    looking_at_robot_ = rng_.bernoulli(share);
    gaze_since_s_ = now_s;
    next_gaze_change_s_ = (next_gaze_change_s_ ? *next_gaze_change_s_ : now_s) +
                          rng_.exponential(params_.gaze_mean_duration_s);
  }
  if (looking_at_robot_) {
    gaze_ = GazeEvent{robot.id, bearing(owner.centre(), robot.centre()), gaze_since_s_};
  } else if (profile_ == ReactionProfile::kAvoid) {
    // Looking anywhere but at ARI: along the body, which turns away from it.
    gaze_ = GazeEvent{model::kNoObject, owner.pose().theta, gaze_since_s_};
  } else {
    gaze_.reset();  // the person's own gaze
  }
}

void RobotReaction::plan_alone(const Object& owner, const StepContext& context,
                               const RobotView& robot) {
  const double distance = robot.distance_to(owner.pose().position);
  // An engaged reaction lasts until ARI is kHysteresisM beyond the distance that started it.
  const bool noticed =
      distance < params_.notice_distance_m + (phase_ == Phase::kEngaged ? kHysteresisM : 0.0);
  if (profile_ == ReactionProfile::kIgnore) {
    return;
  }
  if (profile_ == ReactionProfile::kYield) {
    plan_yield(owner, context, robot);  // yields to ARI's path, however far ARI is
    return;
  }
  // The others react only while ARI is near.
  if (!noticed) {
    reset();
    return;
  }
  if (profile_ == ReactionProfile::kCurious) {
    plan_curious(owner, robot);
  } else if (profile_ == ReactionProfile::kAvoid) {
    plan_avoid(owner, context, robot);
  } else {
    plan_block(owner, robot);
  }
}

Eigen::Vector2d RobotReaction::aside_target(const Object& owner, const StepContext& context,
                                            const RobotView& robot) const {
  const auto& human = static_cast<const Human&>(owner);
  const double radius = human.spec().motion.body_radius_m;
  const Eigen::Vector2d p = owner.pose().position;
  const Eigen::Vector2d along = robot.travel_direction();
  const Eigen::Vector2d left = left_of(along);
  const PathOffset offset = path_offset(robot, p);
  // 0.1 m beyond the corridor's edge, so the person is out of it once there.
  const double clear = robot.footprint.half_width_m + params_.corridor_margin_m + 0.1;
  // The nearer side (the one the person stands on) if free, else the other; then each moved
  // further along ARI's path (a wall beside the path, as by a doorway, shuts a side near it but
  // not further on).
  const double first = offset.lateral_m >= 0.0 ? 1.0 : -1.0;
  Eigen::Vector2d best = p;
  double best_length = std::numeric_limits<double>::infinity();
  for (double ahead : {0.0, 0.5, 1.0, 1.5}) {
    for (double side : {first, -first}) {
      const Eigen::Vector2d target = p + (side * clear - offset.lateral_m) * left + ahead * along;
      const double length = (target - p).norm();
      if (length < best_length && way_is_free(context.simulation, p, target, radius)) {
        best = target;
        best_length = length;
      }
    }
    if (best_length < std::numeric_limits<double>::infinity()) {
      break;  // the least move ahead that frees the way
    }
  }
  return best;
}

void RobotReaction::plan_yield(const Object& owner, const StepContext& context,
                               const RobotView& robot) {
  const auto& human = static_cast<const Human&>(owner);
  const HumanMotionParams& motion = human.spec().motion;
  const Eigen::Vector2d p = owner.pose().position;
  const double now_s = context.time_s + context.dt_s;

  if (in_robot_corridor(robot, p, params_)) {
    // In ARI's way (again): step aside, remembering where the encounter found the person.
    if (phase_ == Phase::kIdle || phase_ == Phase::kReturning || phase_ == Phase::kWaiting) {
      if (phase_ == Phase::kIdle) {
        origin_ = owner.pose();
      }
      aside_target_ = aside_target(owner, context, robot);
      phase_ = Phase::kSteppingAside;
    }
    const Eigen::Vector2d towards_robot = -robot.travel_direction();
    aside_face_rad_ = std::atan2(towards_robot.y(), towards_robot.x());
  }
  if (phase_ == Phase::kIdle) {
    return;
  }

  // The person's place is free again once ARI's corridor leaves it and ARI is clear of it.
  const bool origin_clear =
      !in_robot_corridor(robot, origin_.position, params_) &&
      robot.distance_to(origin_.position) > params_.passed_distance_m + kHysteresisM;
  if (phase_ == Phase::kSteppingAside || phase_ == Phase::kWaiting) {
    // ARI has passed when its rear is passed_distance beyond the person, or it went elsewhere.
    const PathOffset offset = path_offset(robot, p);
    const double length = robot.footprint.front_x_m - robot.footprint.rear_x_m;
    const double distance = robot.distance_to(p);
    const bool passed = (offset.ahead_m < -length - params_.passed_distance_m &&
                         distance > params_.passed_distance_m) ||
                        distance > params_.notice_distance_m;
    if (phase_ == Phase::kSteppingAside && (aside_target_ - p).norm() < kArrivedM) {
      phase_ = Phase::kWaiting;
      waiting_since_s_ = now_s;
    }
    const bool waited_enough =
        phase_ == Phase::kWaiting && now_s - waiting_since_s_ > params_.yield_max_wait_s;
    if ((passed || waited_enough) && origin_clear) {
      phase_ = Phase::kReturning;
    } else {
      // Body along the path, facing where ARI comes from: the narrow side of the personal space
      // toward ARI as it passes; the gaze follows ARI (update_gaze).
      motion_.kind = ReactionMotion::Kind::kReplace;
      motion_.velocity_mps = velocity_toward(p, aside_target_, motion.walking_speed_mps);
      motion_.face_rad = aside_face_rad_;
      return;
    }
  }

  // kReturning: a walker walks on (navigation still holds its goal); a person who stood walks
  // back to their place and heading, unless ARI's corridor covers it.
  if (human.goal()) {
    phase_ = Phase::kIdle;
    return;
  }
  motion_.kind = ReactionMotion::Kind::kReplace;
  if (!origin_clear) {
    return;  // stands where it is until ARI is clear of the place
  }
  const Eigen::Vector2d to_origin = origin_.position - p;
  if (to_origin.norm() > kArrivedM) {
    motion_.velocity_mps = velocity_toward(p, origin_.position, motion.walking_speed_mps);
    motion_.face_rad = bearing(p, origin_.position);
    return;
  }
  motion_.face_rad = origin_.theta;
  if (std::abs(core::angle_difference(origin_.theta, owner.pose().theta)) < 0.05) {
    phase_ = Phase::kIdle;
    motion_ = ReactionMotion{};
  }
}

void RobotReaction::plan_curious(const Object& owner, const RobotView& robot) {
  if (phase_ != Phase::kEngaged) {
    phase_ = Phase::kEngaged;
    origin_ = owner.pose();
    approaches_ = rng_.bernoulli(params_.curious_approach_probability);
  }
  const auto& human = static_cast<const Human&>(owner);
  const double careful = kCarefulShare * human.spec().motion.walking_speed_mps;
  const Eigen::Vector2d p = owner.pose().position;
  const double distance = robot.distance_to(p);
  const Eigen::Vector2d away = away_from(robot, p);
  motion_.kind = ReactionMotion::Kind::kReplace;
  motion_.face_rad = bearing(owner.centre(), robot.centre());
  if (distance < params_.curious_min_distance_m) {
    // Backs off to the least distance, facing ARI; 2/s closes the gap without overshooting.
    motion_.velocity_mps =
        away * std::min(careful, 2.0 * (params_.curious_min_distance_m - distance + 0.02));
  } else if (approaches_ && distance > params_.curious_distance_m + kArrivedM) {
    motion_.velocity_mps = -away * std::min(careful, 2.0 * (distance - params_.curious_distance_m));
  }
}

void RobotReaction::plan_avoid(const Object& owner, const StepContext& context,
                               const RobotView& robot) {
  phase_ = Phase::kEngaged;
  const auto& human = static_cast<const Human&>(owner);
  const HumanMotionParams& motion = human.spec().motion;
  const Eigen::Vector2d p = owner.pose().position;
  const double distance = robot.distance_to(p);
  const Eigen::Vector2d away = away_from(robot, p);
  // Full speed (max_speed, faster than ARI's 1 m/s) 0.2 m inside the kept distance, none 0.3 m
  // outside it: the person stays ahead of a robot driving at them.
  const double shortfall = params_.avoid_distance_m + 0.3 - distance;
  const double speed = motion.max_speed_mps * std::clamp(shortfall / 0.5, 0.0, 1.0);
  Eigen::Vector2d direction = away;
  if (in_robot_corridor(robot, p, params_)) {
    // Out of ARI's path as well as away, or it would chase the person down its length.
    const PathOffset offset = path_offset(robot, p);
    const Eigen::Vector2d side =
        (offset.lateral_m >= 0.0 ? 1.0 : -1.0) * left_of(robot.travel_direction());
    direction = (away + side).normalized();
  }
  if (speed > 0.0) {
    // The free direction closest to the wanted one (walls and furniture probed 0.4 m ahead).
    const double radius = motion.body_radius_m;
    const double wanted = std::atan2(direction.y(), direction.x());
    double best_score = -std::numeric_limits<double>::infinity();
    Eigen::Vector2d best = Eigen::Vector2d::Zero();
    for (int i = 0; i < kAvoidDirections; ++i) {
      const int k = (i + 1) / 2 * (i % 2 == 0 ? 1 : -1);  // 0, -1, 1, -2, 2, ...
      const double angle = wanted + 2.0 * core::kPi * k / kAvoidDirections;
      const Eigen::Vector2d candidate(std::cos(angle), std::sin(angle));
      const double score = candidate.dot(direction);
      if (score > best_score && candidate.dot(away) > -0.2 &&
          way_is_free(context.simulation, p, p + 0.4 * candidate, radius)) {
        best_score = score;
        best = candidate;
      }
    }
    direction = best;
  }
  motion_.velocity_mps = speed * direction;
  motion_.kind = human.motion_mode() == MotionMode::kNavigation && speed <= 0.0
                     ? ReactionMotion::Kind::kNone
                     : ReactionMotion::Kind::kReplace;
  if (motion_.kind == ReactionMotion::Kind::kReplace) {
    // Turned away from ARI: the back, or at least a shoulder, toward it.
    motion_.face_rad = std::atan2(away.y(), away.x());
  }
}

void RobotReaction::plan_block(const Object& owner, const RobotView& robot) {
  phase_ = Phase::kEngaged;
  const auto& human = static_cast<const Human&>(owner);
  const HumanMotionParams& motion = human.spec().motion;
  const Eigen::Vector2d p = owner.pose().position;
  const Eigen::Vector2d heading = robot.pose.heading();
  const double front = robot.footprint.front_x_m;
  Eigen::Vector2d target = robot.pose.transform({front + params_.block_distance_m, 0.0});
  // Behind ARI's front and beside its body: round its side first rather than into it.
  const Eigen::Vector2d local = core::Pose2{p, 0.0}.relative_to(robot.pose).position;
  const double side_clear = robot.footprint.half_width_m + motion.body_radius_m + 0.2;
  if (local.x() < front + motion.body_radius_m && std::abs(local.y()) < side_clear + 0.1) {
    const double side = local.y() >= 0.0 ? 1.0 : -1.0;
    target = robot.pose.transform({front + 0.3, side * side_clear});
  } else if (local.x() < front + motion.body_radius_m) {
    target = robot.pose.transform({front + 0.3, local.y()});
  }
  // ARI's own velocity plus a pull onto the place: a blocker keeps up with ARI, then closes in.
  Eigen::Vector2d velocity = robot.linear_mps * heading + kBlockGain * (target - p);
  if (velocity.norm() > motion.max_speed_mps) {
    velocity *= motion.max_speed_mps / velocity.norm();
  }
  if ((target - p).norm() < 0.5 * kArrivedM && std::abs(robot.linear_mps) < 1e-3) {
    velocity.setZero();
  }
  motion_.kind = ReactionMotion::Kind::kReplace;
  motion_.velocity_mps = velocity;
  motion_.face_rad = bearing(owner.centre(), robot.centre());
}

void RobotReaction::plan_member(const Object& owner, const RobotView& robot) {
  // Group members keep their place in the formation: a sidestep (yield) or a step away (avoid),
  // fading out group_offset from where the encounter found them. Curious and blocking members
  // only look (update_gaze).
  const auto& human = static_cast<const Human&>(owner);
  const Eigen::Vector2d p = owner.pose().position;
  const double distance = robot.distance_to(p);
  Eigen::Vector2d direction = Eigen::Vector2d::Zero();
  if (profile_ == ReactionProfile::kYield && in_robot_corridor(robot, p, params_)) {
    const PathOffset offset = path_offset(robot, p);
    direction = (offset.lateral_m >= 0.0 ? 1.0 : -1.0) * left_of(robot.travel_direction());
  } else if (profile_ == ReactionProfile::kAvoid && distance < params_.avoid_distance_m) {
    direction = away_from(robot, p);
  }
  if (direction.isZero()) {
    if (distance > params_.notice_distance_m + kHysteresisM) {
      phase_ = Phase::kIdle;
    }
    return;
  }
  if (phase_ != Phase::kEngaged) {
    phase_ = Phase::kEngaged;
    origin_ = owner.pose();
  }
  const double moved = (p - origin_.position).dot(direction);
  const double fade = std::clamp(1.0 - moved / std::max(params_.group_offset_m, 1e-6), 0.0, 1.0);
  motion_.kind = ReactionMotion::Kind::kAdd;
  motion_.velocity_mps = kMemberShare * human.spec().motion.walking_speed_mps * fade * direction;
}

}  // namespace ari_social_sim::world
