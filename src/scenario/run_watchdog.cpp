#include "ari_social_sim/scenario/run_watchdog.hpp"

#include "ari_social_sim/core/number_text.hpp"

namespace ari_social_sim::scenario {

void RunWatchdog::expect_world(double wall_s) {
  world_expected_since_s_ = wall_s;
}

void RunWatchdog::world_state(double wall_s) {
  world_expected_since_s_ = wall_s;
}

std::optional<std::string> RunWatchdog::expired(
    double wall_s, const std::string& activity,
    const std::function<bool()>& world_reachable) const {
  if (wall_time_limit_s_ > 0.0 && wall_s - start_wall_s_ > wall_time_limit_s_) {
    return "wall-time limit of " + core::number_text(wall_time_limit_s_) + " s" +
           " reached while " + activity;
  }
  if (world_expected_since_s_ && wall_s - *world_expected_since_s_ > world_timeout_s_) {
    return "no /sim/world_state for " + core::number_text(world_timeout_s_) + " s" +
           (world_reachable() ? " (world paused?)" : " (world_node gone?)") + " while " + activity;
  }
  return std::nullopt;
}

}  // namespace ari_social_sim::scenario
