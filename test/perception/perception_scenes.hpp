#pragma once

// Small perception scenes built inline, shared by the perception tests and
// bench/bench_perception.cpp so that what is measured is what is tested.

#include <cmath>
#include <string>
#include <vector>

#include "ari_social_sim/core/angles.hpp"
#include "ari_social_sim/core/rng.hpp"
#include "ari_social_sim/model/world_description.hpp"
#include "ari_social_sim/perception/ari_sensors.hpp"
#include "ari_social_sim/perception/perception_config.hpp"
#include "ari_social_sim/perception/transient_ids.hpp"
#include "ari_social_sim/perception/visibility.hpp"
#include "ari_social_sim/world/map_sensor.hpp"
#include "ari_social_sim/world/world_snapshot.hpp"

namespace ari_social_sim::perception::test {

constexpr model::ObjectId kAriId = 1;

/// A world snapshot at `time_s` with ARI at `X_map_base` (default: the origin facing +x), its
/// head turned by `head_pan_rad`, and no humans yet.
inline world::WorldSnapshot snapshot_with_ari(double time_s = 0.0,
                                              const core::Pose2& X_map_base = {},
                                              double head_pan_rad = 0.0) {
  world::WorldSnapshot snapshot;
  snapshot.time_s = time_s;
  world::AriSnapshot ari;
  ari.id = kAriId;
  ari.pose = X_map_base;
  ari.head_pan_rad = head_pan_rad;
  snapshot.ari = ari;
  return snapshot;
}

/// A silent human at (x, y) with body and gaze along `theta_rad`, looking at nobody.
inline world::HumanSnapshot human_at(model::ObjectId id, double x, double y, double theta_rad) {
  world::HumanSnapshot human;
  human.id = id;
  human.name = "human " + std::to_string(id);
  human.pose = {{x, y}, theta_rad};
  human.gaze.direction_rad = theta_rad;
  human.age_years = 40.0;
  human.gender = model::Gender::kFemale;
  return human;
}

/// A human at (x, y) facing the point (tx, ty).
inline world::HumanSnapshot human_facing(model::ObjectId id, double x, double y, double tx,
                                         double ty) {
  return human_at(id, x, y, std::atan2(ty - y, tx - x));
}

/// Makes `human` say `content` as an act started at `start_s`, at the word of `word_index`.
inline void speaking(world::HumanSnapshot& human, const std::string& content, double start_s,
                     uint32_t word_index) {
  human.speech.act = "INFORM";
  human.speech.content = content;
  human.speech.start_s = start_s;
  human.speech.word_index = word_index;
  human.speech.is_speaking = true;
  size_t begin = 0;
  for (uint32_t i = 0; i < word_index; ++i) {
    begin = content.find(' ', begin) + 1;
  }
  human.speech.current_word = content.substr(begin, content.find(' ', begin) - begin);
}

/// A 0.1 m thick wall from `from` to `to`, rasterised at 5 cm over a 20 x 20 m floor centred on
/// the origin.
inline model::OccupancyGrid map_with_wall(const Eigen::Vector2d& from, const Eigen::Vector2d& to) {
  model::WorldDescription world;
  world.origin = {-10.0, -10.0};
  world.size = {20.0, 20.0};
  model::StaticObject wall;
  wall.id = 1000;
  wall.type = model::ShapeType::kWall;
  wall.pose.position = 0.5 * (from + to);
  wall.pose.theta = std::atan2(to.y() - from.y(), to.x() - from.x());
  wall.size = {(to - from).norm(), 0.1};
  world.objects.push_back(wall);
  return world::rasterize_static_map(world, 0.05);
}

/// Only the error model under test: everything else off.
inline PerceptionConfig config_without_errors(unsigned seed = 1) {
  PerceptionConfig config;
  config.seed = seed;
  return config.without_errors();
}

/// A tracker (BodyTracker, FaceTracker) run on one snapshot at a time, with its own ids.
template <class Tracker, class Observation>
class TrackerHarness {
 public:
  explicit TrackerHarness(const PerceptionConfig& config)
      : config_(config), ids_(core::Rng(1)), tracker_(config_, ids_, core::Rng(2)) {}

  /// This snapshot's observations, 0.05 s after the previous one; `grid` blocks sight.
  std::vector<Observation> perceive(const world::WorldSnapshot& snapshot,
                                    const model::OccupancyGrid* grid = nullptr) {
    people_.clear();
    for (const world::HumanSnapshot& human : snapshot.humans) {
      people_.push_back(human.pose.position);
    }
    std::vector<Observation> observations;
    tracker_.update(snapshot, AriSensors::of(*snapshot.ari, config_),
                    {grid, 50, &people_, config_.occlusion.person_radius_m}, 0.05, observations);
    return observations;
  }

 private:
  PerceptionConfig config_;
  TransientIds ids_;
  Tracker tracker_;
  std::vector<Eigen::Vector2d> people_;
};

/// A crowd of `count` humans in front of ARI (origin, facing +x): circles of 1-4 people 0.6-0.9
/// m around centres spread over x 1..9 m, y -4..4 m, each facing their circle's centre and
/// looking at a neighbour or at ARI, some talking. Seeded.
inline world::WorldSnapshot crowd_snapshot(size_t count, uint64_t seed, double time_s = 0.0) {
  core::Rng rng(seed);
  world::WorldSnapshot snapshot = snapshot_with_ari(time_s);
  model::ObjectId id = 10;
  while (snapshot.humans.size() < count) {
    const size_t size = std::min<size_t>(count - snapshot.humans.size(), 1 + rng.uniform_index(4));
    const Eigen::Vector2d centre(rng.uniform(1.0, 9.0), rng.uniform(-4.0, 4.0));
    const double radius = rng.uniform(0.6, 0.9);
    const double phase = rng.uniform(0.0, 2.0 * core::kPi);
    const model::ObjectId first = id;
    for (size_t k = 0; k < size; ++k) {
      const double bearing = phase + 2.0 * core::kPi * static_cast<double>(k) / size;
      world::HumanSnapshot human =
          human_facing(id, centre.x() + radius * std::cos(bearing),
                       centre.y() + radius * std::sin(bearing), centre.x(), centre.y());
      human.gaze.target = size > 1 ? first + (k + 1) % size : kAriId;
      if (k == 0 && size > 1) {
        speaking(human, "could you tell me where the waiting room is", time_s - 1.0, 2);
      }
      snapshot.humans.push_back(human);
      ++id;
    }
  }
  return snapshot;
}

}  // namespace ari_social_sim::perception::test
