#pragma once

#include <functional>
#include <optional>
#include <string>

namespace ari_social_sim::scenario {

/// scenario_node's limits in wall time, which the script's sim-time limit cannot enforce: sim
/// time stands still while the world is paused and stops for good when world_node dies.
///  - The wall-time limit covers the whole run, the waits for servers and for the world included
///    (0: none).
///  - The world timeout: no world state for that long while the world should be running (from
///    expect_world(), or from the first state when another node starts the world).
/// Times are wall seconds on any one clock (scenario_node: ros::WallTime).
class RunWatchdog {
 public:
  RunWatchdog(double wall_time_limit_s, double world_timeout_s, double start_wall_s)
      : wall_time_limit_s_(wall_time_limit_s),
        world_timeout_s_(world_timeout_s),
        start_wall_s_(start_wall_s) {}

  /// The world should be stepping from `wall_s` on (scenario_node has just unpaused it).
  void expect_world(double wall_s);
  /// A world state arrived at `wall_s`; from now on the world is expected to keep stepping.
  void world_state(double wall_s);

  /// Why the run must end at `wall_s`, or nothing. `activity` says what the node was doing, for
  /// the reason ("in state ask_help", "waiting for the /tts action server"). `world_reachable` is
  /// asked only once the world timeout has passed, to tell a world_node gone from a world paused.
  /// e.g. `no /sim/world_state for 10 s (world_node gone?) while in state ask_help`,
  /// `wall-time limit of 240 s reached while waiting for the /tts action server`.
  std::optional<std::string> expired(double wall_s, const std::string& activity,
                                     const std::function<bool()>& world_reachable) const;

 private:
  double wall_time_limit_s_;
  double world_timeout_s_;
  double start_wall_s_;
  std::optional<double> world_expected_since_s_;  // last state, or when the world was started
};

}  // namespace ari_social_sim::scenario
