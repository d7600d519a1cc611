#include "ari_social_sim/navigation/policy_observation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ari_social_sim/core/config_check.hpp"

namespace ari_social_sim::navigation {
namespace {

constexpr int kPersonFeatures = 9;
constexpr float kInf = std::numeric_limits<float>::infinity();

// A point of the map frame in ARI's base_footprint frame.
Eigen::Vector2d to_robot(const core::Pose2& robot, const Eigen::Vector2d& point) {
  const Eigen::Vector2d d = point - robot.position;
  const double c = std::cos(robot.theta), s = std::sin(robot.theta);
  return {c * d.x() + s * d.y(), -s * d.x() + c * d.y()};
}

Eigen::Vector2d rotate_to_robot(const core::Pose2& robot, const Eigen::Vector2d& vector) {
  const double c = std::cos(robot.theta), s = std::sin(robot.theta);
  return {c * vector.x() + s * vector.y(), -s * vector.x() + c * vector.y()};
}

bool blocked(const model::OccupancyGrid& map, const Eigen::Vector2d& point) {
  int x = 0, y = 0;
  if (!map.cell_of(point, x, y)) {
    return true;
  }
  const int8_t value = map.at(x, y);
  return value == model::OccupancyGrid::kUnknown || value >= 50;
}

}  // namespace

void PolicyObservationConfig::validate() const {
  core::check_fields(*this, "PolicyObservationConfig");
}

PolicyObservation::PolicyObservation(const PolicyObservationConfig& config)
    : config_(core::validated(config)) {
  auto add = [this](const char* name, int size, float low, float high) {
    fields_.push_back({name, size_, size, low, high});
    size_ += size;
  };
  add("robot", 3, -kInf, kInf);
  add("goal", 6, -kInf, kInf);
  add("group", 4, -kInf, kInf);
  add("people", kPersonFeatures * config_.nearest_people, -kInf, kInf);
  add("occupancy", config_.patch_cells * config_.patch_cells, 0.0f, 1.0f);
}

void PolicyObservation::build(const RobotObservation& robot, const PerceivedScene& scene,
                              const std::optional<Goal>& goal, bool goal_perceived,
                              const model::OccupancyGrid& map, float* out) const {
  std::fill(out, out + size_, 0.0f);
  const core::Pose2& pose = robot.pose;
  float* at = out;
  at[0] = static_cast<float>(robot.linear_mps);
  at[1] = static_cast<float>(robot.angular_rps);
  at[2] = static_cast<float>(robot.pan_rad);
  at += 3;

  const GroupEstimate* joined = nullptr;
  if (goal) {
    const Eigen::Vector2d g = to_robot(pose, goal->pose.position);
    const double relative = goal->pose.theta - pose.theta;
    at[0] = goal_perceived ? 1.0f : 0.0f;
    at[1] = static_cast<float>(g.x());
    at[2] = static_cast<float>(g.y());
    at[3] = static_cast<float>(std::cos(relative));
    at[4] = static_cast<float>(std::sin(relative));
    at[5] = static_cast<float>(g.norm());
    if (!goal->group_id.empty()) {
      joined = scene.find_group(goal->group_id);
    }
  }
  at += 6;

  if (joined != nullptr) {
    const Eigen::Vector2d c = to_robot(pose, joined->centre);
    at[0] = 1.0f;
    at[1] = static_cast<float>(c.x());
    at[2] = static_cast<float>(c.y());
    at[3] = static_cast<float>(joined->radius_m);
  }
  at += 4;

  write_people(pose, scene, goal, at);
  at += kPersonFeatures * config_.nearest_people;
  write_occupancy(pose, map, at);
}

// The K nearest within range, nearest first (ties by id, so that the order never depends on the
// order perception listed them in), kPersonFeatures values each.
void PolicyObservation::write_people(const core::Pose2& pose, const PerceivedScene& scene,
                                     const std::optional<Goal>& goal, float* at) const {
  std::vector<std::pair<double, const PersonEstimate*>> near;
  near.reserve(scene.people.size());
  for (const PersonEstimate& person : scene.people) {
    const double distance = (person.position - pose.position).norm();
    if (distance <= config_.people_range_m) {
      near.emplace_back(distance, &person);
    }
  }
  const size_t shown = std::min(near.size(), static_cast<size_t>(config_.nearest_people));
  std::partial_sort(near.begin(), near.begin() + static_cast<std::ptrdiff_t>(shown), near.end(),
                    [](const auto& a, const auto& b) {
                      return a.first != b.first ? a.first < b.first : a.second->id < b.second->id;
                    });
  for (size_t i = 0; i < shown; ++i) {
    const PersonEstimate& person = *near[i].second;
    float* p = at + kPersonFeatures * i;
    const Eigen::Vector2d position = to_robot(pose, person.position);
    const Eigen::Vector2d velocity = rotate_to_robot(pose, person.velocity);
    const double facing = person.heading - pose.theta;
    p[0] = 1.0f;
    p[1] = static_cast<float>(position.x());
    p[2] = static_cast<float>(position.y());
    p[3] = static_cast<float>(velocity.x());
    p[4] = static_cast<float>(velocity.y());
    p[5] = static_cast<float>(std::cos(facing));
    p[6] = static_cast<float>(std::sin(facing));
    p[7] = goal && goal->is_target(person.id) ? 1.0f : 0.0f;
    p[8] = scene.group_of(person.id) != nullptr ? 1.0f : 0.0f;
  }
}

// A patch_cells x patch_cells occupancy patch centred on ARI, rows along its heading.
void PolicyObservation::write_occupancy(const core::Pose2& pose, const model::OccupancyGrid& map,
                                        float* at) const {
  const int cells = config_.patch_cells;
  const double half = 0.5 * (cells - 1);
  const Eigen::Vector2d forward = pose.heading();
  const Eigen::Vector2d left(-forward.y(), forward.x());
  for (int i = 0; i < cells; ++i) {
    const Eigen::Vector2d row = pose.position + (i - half) * config_.patch_resolution_m * forward;
    for (int j = 0; j < cells; ++j) {
      const Eigen::Vector2d point = row + (j - half) * config_.patch_resolution_m * left;
      at[i * cells + j] = blocked(map, point) ? 1.0f : 0.0f;
    }
  }
}

}  // namespace ari_social_sim::navigation
