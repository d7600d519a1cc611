#include "ari_social_sim/navigation/goal_finder.hpp"

#include <algorithm>
#include <cmath>

#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/core/format_text.hpp"
#include "ari_social_sim/navigation/goal_request.hpp"
#include "ari_social_sim/navigation/social_spaces.hpp"

namespace ari_social_sim::navigation {
namespace {

constexpr double kTwoPi = 2.0 * core::kPi;
// Spacing of the footprint outline points that test personal spaces.
constexpr double kOutlineSpacing = 0.1;

Eigen::Vector2d unit(double angle) {
  return {std::cos(angle), std::sin(angle)};
}

struct Gap {
  double start;  // rad, angle of the member where the gap begins (counter-clockwise)
  double width;  // rad
  double bisector() const { return core::wrap_angle(start + 0.5 * width); }
  bool contains(double angle) const {
    const double from_start = std::fmod(angle - start + 2.0 * kTwoPi, kTwoPi);
    return from_start <= width;
  }
};

// Gaps between consecutive members around the centre, widest first (one full gap for one member).
std::vector<Gap> gaps_around(const Eigen::Vector2d& centre,
                             const std::vector<const PersonEstimate*>& members) {
  std::vector<double> angles;
  for (const PersonEstimate* member : members) {
    const Eigen::Vector2d d = member->position - centre;
    angles.push_back(std::atan2(d.y(), d.x()));
  }
  std::sort(angles.begin(), angles.end());
  std::vector<Gap> gaps;
  for (size_t i = 0; i < angles.size(); ++i) {
    const double next = i + 1 < angles.size() ? angles[i + 1] : angles[0] + kTwoPi;
    gaps.push_back({angles[i], next - angles[i]});
  }
  std::stable_sort(gaps.begin(), gaps.end(),
                   [](const Gap& a, const Gap& b) { return a.width > b.width; });
  return gaps;
}

}  // namespace

std::string describe(const NavigationTarget& target) {
  if (const auto* pose = std::get_if<PoseTarget>(&target)) {
    return "pose " + core::point_text(pose->pose.position);
  }
  if (const auto* person = std::get_if<PersonTarget>(&target)) {
    return "person " + person->person_id;
  }
  if (const auto* group = std::get_if<GroupTarget>(&target)) {
    return "group " + group->group_id;
  }
  return "the group of person " + std::get<GroupOfPersonTarget>(target).person_id;
}

std::string unknown_target_reason(const NavigationTarget& target, const PerceivedScene& scene) {
  if (const auto* person = std::get_if<PersonTarget>(&target)) {
    return scene.find_person(person->person_id) ? ""
                                                : "person " + person->person_id + " is not tracked";
  }
  if (const auto* group = std::get_if<GroupTarget>(&target)) {
    return scene.find_group(group->group_id) ? "" : "group " + group->group_id + " is not reported";
  }
  if (const auto* member = std::get_if<GroupOfPersonTarget>(&target)) {
    if (!scene.find_person(member->person_id)) {
      return "person " + member->person_id + " is not tracked";
    }
    return scene.group_of(member->person_id) ? ""
                                             : "person " + member->person_id + " is in no group";
  }
  return "";
}

GoalFinder::GoalFinder(const GoalFinderConfig& config, const FootprintModel& footprint,
                       const PersonalSpaceParams& spaces)
    : config_(config), footprint_(footprint), spaces_(spaces) {}

GoalSearch GoalFinder::find(const NavigationTarget& target, const PerceivedScene& scene,
                            const GridField& sdf, const core::Pose2& robot,
                            const std::optional<Goal>& previous) const {
  if (const auto* pose = std::get_if<PoseTarget>(&target)) {
    return find_pose(*pose, sdf);
  }
  const std::string unknown = unknown_target_reason(target, scene);
  if (!unknown.empty()) {
    return GoalFailure{GoalFailure::Kind::kUnknownTarget, unknown};
  }
  if (const auto* person = std::get_if<PersonTarget>(&target)) {
    return find_person(*scene.find_person(person->person_id), scene, sdf, robot, previous);
  }
  const GroupEstimate* group =
      std::holds_alternative<GroupTarget>(target)
          ? scene.find_group(std::get<GroupTarget>(target).group_id)
          : scene.group_of(std::get<GroupOfPersonTarget>(target).person_id);
  return find_group(*group, scene, sdf, robot, previous);
}

bool GoalFinder::is_free(const core::Pose2& base, const PerceivedScene& scene, const GridField& sdf,
                         double margin_m) const {
  const Eigen::Vector2d axis = base.heading();
  for (double offset : footprint_.circle_offsets_x_m) {
    if (sdf.sample(base.position + offset * axis) < footprint_.circle_radius_m + margin_m) {
      return false;
    }
  }
  for (const PersonEstimate& person : scene.people) {
    if (footprint_.distance_to(base, person.position) < spaces_.person_radius_m + margin_m) {
      return false;
    }
  }
  return true;
}

bool GoalFinder::is_polite(const core::Pose2& base, const PerceivedScene& scene,
                           const std::string& group_id,
                           const std::vector<std::string>& exempt) const {
  for (const GroupEstimate& group : scene.groups) {
    if (group.id != group_id &&
        footprint_.distance_to(base, group.centre) < ospace_radius(group, spaces_)) {
      return false;
    }
  }
  const std::vector<Eigen::Vector2d> outline = footprint_.outline(kOutlineSpacing);
  const double edge = spaces_.boundary_value();
  for (const PersonEstimate& person : scene.people) {
    if (std::find(exempt.begin(), exempt.end(), person.id) != exempt.end()) {
      continue;
    }
    for (const Eigen::Vector2d& point : outline) {
      if (personal_space_value(person, spaces_, base.transform(point), 0.0) >= edge) {
        return false;
      }
    }
  }
  return true;
}

core::Pose2 GoalFinder::base_for_body_centre(const Eigen::Vector2d& body_centre,
                                             double heading) const {
  core::Pose2 base;
  base.theta = core::wrap_angle(heading);
  base.position = body_centre - footprint_.rectangle.centre_local().x() * base.heading();
  return base;
}

GoalSearch GoalFinder::find_pose(const PoseTarget& target, const GridField& sdf) const {
  int x, y;
  if (!sdf.cell_of(target.pose.position, x, y)) {
    return GoalFailure{GoalFailure::Kind::kUnreachable,
                       "goal " + core::point_text(target.pose.position) +
                           " is outside the map, which spans " + MapBounds::of(sdf).describe()};
  }
  const PerceivedScene nobody;
  if (!is_free(target.pose, nobody, sdf, 0.0)) {
    return GoalFailure{GoalFailure::Kind::kUnreachable,
                       "goal " + core::point_text(target.pose.position) +
                           ": ARI's footprint there overlaps a wall or furniture"};
  }
  Goal goal;
  goal.pose = target.pose;
  return goal;
}

GoalSearch GoalFinder::find_person(const PersonEstimate& person, const PerceivedScene& scene,
                                   const GridField& sdf, const core::Pose2& robot,
                                   const std::optional<Goal>& previous) const {
  const std::vector<std::string> exempt = {person.id};
  auto place = [&](double offset, double distance) {
    const double direction = person.heading + offset;
    core::Pose2 base;
    base.position = person.position + distance * unit(direction);
    base.theta = core::wrap_angle(direction + core::kPi);
    return base;
  };
  // Candidate offsets from the person's facing direction: 0, then +-s, +-2s, ... up to the
  // maximum, the side nearer to ARI first.
  std::vector<double> offsets = {0.0};
  for (double a = config_.approach_angle_step; a <= config_.approach_max_angle + 1e-9;
       a += config_.approach_angle_step) {
    const double to_left = (place(a, config_.approach_distance_m).position - robot.position).norm();
    const double to_right =
        (place(-a, config_.approach_distance_m).position - robot.position).norm();
    offsets.push_back(to_left <= to_right ? a : -a);
    offsets.push_back(to_left <= to_right ? -a : a);
  }
  // The previous goal's offset first, while it stays free.
  if (previous && !previous->target_people.empty() && previous->target_people[0] == person.id &&
      previous->group_id.empty()) {
    const Eigen::Vector2d d = previous->pose.position - person.position;
    const double kept = core::angle_difference(std::atan2(d.y(), d.x()), person.heading);
    if (std::abs(kept) <= config_.approach_max_angle + 1e-9) {
      offsets.insert(offsets.begin(), kept);
    }
  }
  for (int pass = 0; pass < 3; ++pass) {
    // Pass 0: polite places at the comfortable distance; 1: any free one; 2: a little farther.
    const double distance = config_.approach_distance_m + (pass == 2 ? 0.3 : 0.0);
    for (double offset : offsets) {
      const core::Pose2 base = place(offset, distance);
      if (!is_free(base, scene, sdf, config_.free_margin_m)) {
        continue;
      }
      if (pass == 0 && !is_polite(base, scene, "", exempt)) {
        continue;
      }
      Goal goal;
      goal.pose = base;
      goal.look_at = person.position;
      goal.target_people = exempt;
      return goal;
    }
  }
  return GoalFailure{
      GoalFailure::Kind::kUnreachable,
      "no free place in front of person " + person.id + " at " + core::point_text(person.position)};
}

GoalSearch GoalFinder::find_group(const GroupEstimate& group, const PerceivedScene& scene,
                                  const GridField& sdf, const core::Pose2& robot,
                                  const std::optional<Goal>& previous) const {
  std::vector<const PersonEstimate*> members;
  for (const std::string& id : group.members) {
    if (const PersonEstimate* person = scene.find_person(id)) {
      members.push_back(person);
    }
  }
  const Eigen::Vector2d& centre = group.centre;
  const double radius = group.radius_m;
  std::vector<Gap> gaps = gaps_around(centre, members);
  if (gaps.empty()) {
    gaps.push_back({0.0, kTwoPi});
  }
  const double needed_arc = 2.0 * footprint_.rectangle.half_width_m + 2.0 * config_.gap_clearance_m;
  auto make_goal = [&](const Gap& gap, double body_radius, bool outside) {
    const double angle = gap.bisector();
    Goal goal;
    goal.pose = base_for_body_centre(centre + body_radius * unit(angle), angle + core::kPi);
    goal.look_at = centre;
    goal.group_id = group.id;
    goal.target_people = group.members;
    goal.gap_angle = angle;
    goal.gap_width = gap.width;
    goal.outside_circle = outside;
    return goal;
  };
  // Gaps within the width tolerance of one another are as good as each other: within each such
  // run (widest first), the one nearest ARI comes first, so ARI does not go round the group for a
  // gap a few degrees wider.
  for (auto run = gaps.begin(); run != gaps.end();) {
    const double widest = run->width;
    const auto run_end = std::find_if(run, gaps.end(), [&](const Gap& gap) {
      return gap.width < widest - config_.gap_width_tolerance;
    });
    std::stable_sort(run, run_end, [&](const Gap& a, const Gap& b) {
      return (make_goal(a, radius, false).pose.position - robot.position).norm() <
             (make_goal(b, radius, false).pose.position - robot.position).norm();
    });
    run = run_end;
  }
  // A gap used before comes first while it still has room.
  if (previous && previous->group_id == group.id) {
    const auto kept = std::find_if(gaps.begin(), gaps.end(), [&](const Gap& gap) {
      return gap.contains(previous->gap_angle);
    });
    if (kept != gaps.end()) {
      std::rotate(gaps.begin(), kept, kept + 1);
    }
  }
  // On the circle: polite places first, then any free one.
  for (int pass = 0; pass < 2; ++pass) {
    for (const Gap& gap : gaps) {
      if (radius * gap.width < needed_arc) {
        continue;
      }
      Goal goal = make_goal(gap, radius, false);
      if (is_free(goal.pose, scene, sdf, config_.free_margin_m) &&
          (pass == 1 || is_polite(goal.pose, scene, group.id, group.members))) {
        return goal;
      }
    }
  }
  // Just outside the circle, stepping out until the footprint is free.
  constexpr int kOutwardSteps = 6;
  constexpr double kOutwardStep = 0.1;
  for (const Gap& gap : gaps) {
    for (int k = 0; k < kOutwardSteps; ++k) {
      Goal goal = make_goal(gap, radius + config_.outside_offset_m + k * kOutwardStep, true);
      if (is_free(goal.pose, scene, sdf, config_.free_margin_m)) {
        return goal;
      }
    }
  }
  return GoalFailure{GoalFailure::Kind::kUnreachable,
                     "group " + group.id + " at " + core::point_text(centre) +
                         ": no gap with room for ARI and no free place just outside it"};
}

}  // namespace ari_social_sim::navigation
