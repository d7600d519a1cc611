#pragma once

#include <cmath>
#include <deque>
#include <optional>
#include <utility>
#include <vector>

#include "ari_social_sim/physics/person_shape.hpp"

// The 2D world's reports of its people, each taken when the physics reaches the time it
// describes. world_node publishes its state at s once it has stepped to s; the physics steps
// from the state before, s_prev, up to s and should draw, over (s_prev, s], the people of s walked
// on (rendering::DrawnPeople poses them so for a reader of the images). A physics that runs
// behind the world on a busy machine has newer states waiting: taking the newest at once would
// draw people a world step or more ahead of the images' stamps.

namespace ari_social_sim::physics {

class PeopleReports {
 public:
  /// How many reports wait at most: two seconds of world_node's default 0.05 s step.
  static constexpr size_t kCapacity = 40;

  /// Queues the people of the world state stamped `time_s`. A stamp earlier than the last
  /// queued (the world was reset) drops the queue. Beyond kCapacity the oldest is dropped.
  void add(double time_s, std::vector<PersonState> people);

  /// The report to draw from for the physics step ending at `step_end_s`: the first stamped no
  /// earlier than it (older ones are dropped), else the newest there is. nullopt when that
  /// report was already handed out, or nothing was ever queued.
  std::optional<std::vector<PersonState>> take_for(double step_end_s);

  /// Whether the report for the physics' time `time_s` has come (one stamped no earlier), or none
  /// ever did: stepping to `time_s` without it would draw the report before.
  bool has_report_for(double time_s) const;

 private:
  std::deque<std::pair<double, std::vector<PersonState>>> reports_;
  std::optional<double> newest_s_;
  std::optional<double> handed_out_s_;  // the stamp of the report last handed out
};

}  // namespace ari_social_sim::physics
