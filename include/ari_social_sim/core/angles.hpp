#pragma once

#include <cmath>

namespace ari_social_sim::core {

constexpr double kPi = 3.14159265358979323846;

/// Wraps an angle (rad) into [-pi, pi).
inline double wrap_angle(double angle_rad) {
  const double wrapped = std::fmod(angle_rad + kPi, 2.0 * kPi);
  return (wrapped < 0.0 ? wrapped + 2.0 * kPi : wrapped) - kPi;
}

/// Signed smallest rotation (rad) that turns `from_rad` onto `to_rad`, in [-pi, pi).
inline double angle_difference(double to_rad, double from_rad) {
  return wrap_angle(to_rad - from_rad);
}

inline double deg_to_rad(double deg) {
  return deg * kPi / 180.0;
}
inline double rad_to_deg(double rad) {
  return rad * 180.0 / kPi;
}

}  // namespace ari_social_sim::core
