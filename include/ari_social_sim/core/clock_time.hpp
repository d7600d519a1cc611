#pragma once

#include <cmath>
#include <cstdint>

namespace ari_social_sim::core {

/// Sim time (s) after `steps` steps of `step_s`, counted in whole nanoseconds (the step rounded
/// to one) and read as ROS reads its time stamps: the whole seconds plus 1e-9 times the remaining
/// nanoseconds (ros::Time::toSec). A stamp of it therefore reads back the very same double, so
/// that the nodes, which get the time from /clock and message stamps, and the in-process engine,
/// which gets it directly, compute with the same times. (0.05 s steps counted as doubles reach
/// 0.15000000000000002 s at the third, which a stamp reads back as 0.15 s.)
inline double clock_time_s(uint64_t steps, double step_s) {
  const auto step_ns = static_cast<uint64_t>(std::llround(step_s * 1e9));
  const uint64_t ns = steps * step_ns;
  const uint64_t whole_s = ns / 1000000000u;  // whole seconds, exactly
  return static_cast<double>(whole_s) + 1e-9 * static_cast<double>(ns % 1000000000u);
}

}  // namespace ari_social_sim::core
